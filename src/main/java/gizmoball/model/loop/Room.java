package gizmoball.model.loop;

import gizmoball.model.gizmo.GizmoBase;

import java.util.ArrayList;
import java.util.List;

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
        return at(view, ball, p, new ArrayList<>(4));
    }

    /**
     * {@link #at(LoopView, Ball, Vect)}, finding the gizmos near {@code p} into {@code nearby} (emptied first; the
     * caller's, kept): a ball held on a surface asks at every tick it drifts.
     */
    static boolean at(LoopView view, Ball ball, Vect p, List<GizmoBase> nearby) {
        double r = Arena.BALL_RADIUS;
        double inner = r - Tolerances.CONTACT;
        if (p.x() < inner || p.y() < inner || p.x() > Arena.SIZE - inner || p.y() > Arena.SIZE - inner) {
            return false;
        }
        view.index().within(p.x() - r, p.y() - r, p.x() + r, p.y() + r, nearby);
        for (int i = 0; i < nearby.size(); i++) {
            if (nearby.get(i).signedDistance(p) < inner) {
                return false;
            }
        }
        double apart = 2 * r - Tolerances.CONTACT;
        List<Ball> balls = view.balls();
        for (int i = 0; i < balls.size(); i++) {
            Ball other = balls.get(i);
            // p.distanceSquared(other.position()), on the components: the far balls, nearly all, make no vector
            double dx = p.x() - other.x();
            double dy = p.y() - other.y();
            if (dx * dx + dy * dy < apart * apart && other != ball && !other.isCaptured()
                    && !view.passingThrough(ball, other)) {
                return false;
            }
        }
        return true;
    }
}
