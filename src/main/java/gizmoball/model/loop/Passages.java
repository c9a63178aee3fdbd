package gizmoball.model.loop;

import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.Passage;
import gizmoball.model.gizmo.Portal;

/**
 * Portals as the loop meets them (docs/design.md, "Portals"): a ball touching the open mouth of a portal (one with a
 * pair) goes through it when the spot where it would leave the pair is clear of walls, gizmos and other balls. Then
 * the mouth is nothing to it: never a contact that holds it, never a row of a cluster, and meeting it is a passage
 * ({@link StillSurfaces}). Where the spot is taken the mouth is a wall like any other, until the spot clears.
 */
final class Passages {
    private Passages() {
    }

    /** The passage the ball takes through segment {@code segment} of the gizmo, or null if it is a wall to the ball. */
    static Passage through(LoopView view, Ball ball, GizmoBase gizmo, int segment) {
        if (!(gizmo instanceof Portal portal) || !portal.opensAt(segment)
                || !(view.gizmo(portal.pair().orElseThrow()) instanceof Portal exit)) {
            return null;
        }
        Passage out = portal.passage(ball.position(), ball.velocity(), exit, Arena.BALL_RADIUS);
        return Room.at(view, ball, out.centre()) ? out : null;
    }

    /** The passage the ball takes through what it meets, or null: it is no open mouth with room beyond. */
    static Passage of(LoopView view, Ball ball, Contact contact) {
        return contact instanceof Contact.Face face ? through(view, ball, face.gizmo(), face.index()) : null;
    }
}
