package gizmoball.model;

import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.loop.Arena;
import gizmoball.model.loop.Tolerances;

import physics.Vect;

/**
 * Whether a ball placed somewhere overlaps a gizmo or another ball by more than touching: the one home of the
 * placement rule that the editor, the loader, a capture and a launch all use (docs/design.md, "Tolerances").
 */
final class Overlaps {
    private Overlaps() {
    }

    /** A ball centred at p is inside the gizmo's body by more than {@link Tolerances#PLACEMENT}. */
    static boolean ballInGizmo(GizmoBase gizmo, Vect p) {
        return gizmo.signedDistance(p) < Arena.BALL_RADIUS - Tolerances.PLACEMENT;
    }

    /** Balls centred at a and b overlap by more than {@link Tolerances#PLACEMENT}. */
    static boolean balls(Vect a, Vect b) {
        return Math.sqrt(a.distanceSquared(b)) < 2 * Arena.BALL_RADIUS - Tolerances.PLACEMENT;
    }
}
