package gizmoball.lab;

import gizmoball.model.Board;

/**
 * Plays a board through its public API only, as a person at the keys would: before each tick it reads the balls
 * and gizmos and presses or releases the board's keys. All its timing is in the board's ticks, and its chances come
 * from its own seeded generator, so a player and a board give the same game every time.
 */
public interface Player {
    /** Looks at the board and presses or releases keys; called before each tick. */
    void beforeTick(Board board);
}
