package gizmoball.model;

import gizmoball.model.loop.LoopView;

/**
 * A board's {@link LoopView}, for the loop's own tests in {@code gizmoball.model.loop} (a detector or schedule run on
 * a real board). Only the board's loop reads it, so {@link Board} keeps it package-private and tests elsewhere reach
 * it through this fixture.
 */
public final class LoopViews {
    private LoopViews() {
    }

    public static LoopView of(Board board) {
        return board.loopView();
    }
}
