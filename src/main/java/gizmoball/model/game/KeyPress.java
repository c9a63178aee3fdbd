package gizmoball.model.game;

/**
 * A key going down or up when the board had run {@code tick} ticks (so it acts in tick {@code tick + 1}): what a game
 * records of its player, and all a replay needs besides the board as built.
 */
public record KeyPress(long tick, Motion motion, int keyCode) {

    public enum Motion { DOWN, UP }

    public KeyPress {
        if (tick < 0) {
            throw new IllegalArgumentException("a key press has a tick of 0 or more, not " + tick);
        }
        if (motion == null) {
            throw new IllegalArgumentException("a key press goes down or up");
        }
    }
}
