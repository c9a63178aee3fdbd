package gizmoball.model;

import gizmoball.model.loop.LoopMode;

/**
 * The loop mode of a board, for tests outside the model package (the stability tests play every scene in both
 * modes). The game always plays {@link LoopMode#CONTINUOUS}, so the switch is package-private on {@link Board}
 * and tests elsewhere reach it through this fixture.
 */
public final class LoopModes {
    private LoopModes() {
    }

    public static void set(Board board, LoopMode mode) {
        board.setLoopMode(mode);
    }

    public static LoopMode of(Board board) {
        return board.loopView().loopMode();
    }
}
