package gizmoball.editor;

import gizmoball.model.Board;
import gizmoball.model.gizmo.GizmoKind;

/**
 * Picks the first unused name of the form prefix + number (S1, C2, LF1, B3 ...). Gizmos and balls share one
 * namespace on the board, so a name is free only when neither a gizmo nor a ball has it.
 */
public final class NameGenerator {
    public static final String BALL_PREFIX = "B";

    private final Board board;

    public NameGenerator(Board board) {
        this.board = board;
    }

    public String nextGizmoName(GizmoKind kind) {
        return next(kind.namePrefix());
    }

    public String nextBallName() {
        return next(BALL_PREFIX);
    }

    private String next(String prefix) {
        for (int n = 1; ; n++) {
            String name = prefix + n;
            if (board.gizmo(name).isEmpty() && board.ball(name).isEmpty()) {
                return name;
            }
        }
    }
}
