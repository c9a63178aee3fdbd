package gizmoball.model.game;

import gizmoball.model.gizmo.GizmoKind;

/** What a real hit on a gizmo scores unless the board gives that gizmo a value of its own. */
public final class Points {
    /** A gizmo's own value lies within plus or minus this (a board's score must stay far from overflow). */
    public static final int LIMIT = 1_000_000;

    private Points() {
    }

    /**
     * The bumpers score, the more the harder they are to hit (an accelerator a little: it is easy to hit again; a
     * drop target most, hit once until it is raised again);
     * flippers, absorbers and sinks, like the walls, score nothing unless the board says (a sink scores when it
     * takes a ball).
     */
    public static int defaultFor(GizmoKind kind) {
        return switch (kind) {
            case SQUARE -> 10;
            case TRIANGLE -> 25;
            case CIRCLE -> 50;
            case ACCELERATOR -> 20;
            case DROP_TARGET -> 100;
            case SPINNER -> 5;
            case LEFT_FLIPPER, RIGHT_FLIPPER, ABSORBER, SINK, SPAWNER, GATE -> 0;
        };
    }
}
