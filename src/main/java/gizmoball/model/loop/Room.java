package gizmoball.model.loop;

import gizmoball.model.gizmo.GizmoBase;

import physics.Vect;

/**
 * Whether a ball has room at a spot: where a contact puts a ball back on its surface, and where a portal puts it
 * out, nothing may be in the way.
 */
final class Room {
    private Room() {
    }

    /** Whether the ball could lie at {@code p} without entering a wall, a gizmo or another ball. */
    static boolean at(LoopView view, Ball ball, Vect p) {
        double r = Arena.BALL_RADIUS;
        double inner = r - Tolerances.CONTACT;
        if (p.x() < inner || p.y() < inner || p.x() > Arena.SIZE - inner || p.y() > Arena.SIZE - inner) {
            return false;
        }
        for (GizmoBase gizmo : view.index().within(p.x() - r, p.y() - r, p.x() + r, p.y() + r)) {
            if (gizmo.signedDistance(p) < inner) {
                return false;
            }
        }
        double apart = 2 * r - Tolerances.CONTACT;
        for (Ball other : view.balls()) {
            if (other != ball && !other.isCaptured() && !view.passingThrough(ball, other)
                    && p.distanceSquared(other.position()) < apart * apart) {
                return false;
            }
        }
        return true;
    }
}
