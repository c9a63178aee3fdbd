package gizmoball.replay;

import gizmoball.model.Board;
import gizmoball.model.game.KeyPress;
import java.util.List;

/**
 * Plays a board to a key script: before each tick, the keys whose tick is the number of ticks run so far. The same
 * board and script give the same game, bit for bit, whoever plays them (the headless runner, a replay, a test).
 */
public final class ScriptedPlay {
    private final Board board;
    private final List<KeyPress> keys;
    private final double dt;
    private int next;

    /** Keys before the board's present tick are taken as done. */
    public ScriptedPlay(Board board, KeyScript script, double dt) {
        this.board = board;
        this.keys = script.keys();
        this.dt = dt;
        while (next < keys.size() && keys.get(next).tick() < board.ticks()) {
            next++;
        }
    }

    /** Presses the keys due now, then runs one tick. */
    public void tick() {
        pressDueKeys();
        board.tick(dt);
    }

    /** Runs ticks until the board has run {@code ticks}, then presses the keys due at that tick. */
    public void playUntil(long ticks) {
        while (board.ticks() < ticks) {
            tick();
        }
        pressDueKeys();
    }

    private void pressDueKeys() {
        while (next < keys.size() && keys.get(next).tick() == board.ticks()) {
            KeyPress key = keys.get(next++);
            if (key.motion() == KeyPress.Motion.DOWN) {
                board.keyDown(key.keyCode());
            } else {
                board.keyUp(key.keyCode());
            }
        }
    }

    /** Plays a whole script on a board from where it stands. */
    public static Board play(Board board, KeyScript script, long ticks, double dt) {
        new ScriptedPlay(board, script, dt).playUntil(ticks);
        return board;
    }
}
