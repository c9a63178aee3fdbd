package gizmoball.model.game;

import gizmoball.model.gizmo.GizmoKind;

/** What a real hit on a gizmo scores unless the board gives that gizmo a value of its own. */
public final class Points {
    /** A gizmo's own value lies within plus or minus this (a board's score must stay far from overflow). */
    public static final int LIMIT = 1_000_000;

    private Points() {
    }

    /** What a real hit on a gizmo of the kind scores unless the board gives the gizmo its own. */
    public static int defaultFor(GizmoKind kind) {
        return kind.defaultPoints();
    }
}
