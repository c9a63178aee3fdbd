package gizmoball.bench;

import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import physics.Vect;

import java.util.List;

/**
 * Counts what must never happen, from the balls' positions and the gizmos' shapes alone (independently of
 * the model's collision code and of the wording of its messages): a non-finite ball state, a ball whose
 * centre has left the board (escape), and a ball inside a wall, a bumper, a flipper or another ball by
 * more than {@link #TOLERANCE} (penetration). Captured balls sit inside their absorber by design and are
 * skipped; absorbers capture on contact and so are not obstacles here.
 */
final class Probe {

    static final double TOLERANCE = 1e-6;

    /** Counts over a run: ball-ticks with each kind of fault, and the deepest penetration seen. */
    static final class Tally {
        long nonFinite;
        long escapes;
        long penetrations;
        double deepest;
    }

    private Probe() {
    }

    /** Adds the current faults to the tally. */
    static void check(Stepper stepper, Tally tally) {
        List<BallState> balls = stepper.balls();
        List<Gizmo> gizmos = stepper.gizmos();
        for (int i = 0; i < balls.size(); i++) {
            BallState ball = balls.get(i);
            if (ball.captured()) {
                continue;
            }
            Vect c = ball.position();
            Vect v = ball.velocity();
            if (!Double.isFinite(c.x()) || !Double.isFinite(c.y()) || !Double.isFinite(v.x()) || !Double.isFinite(v.y())) {
                tally.nonFinite++;
                continue;
            }
            if (c.x() < 0 || c.x() > Board.SIZE || c.y() < 0 || c.y() > Board.SIZE) {
                tally.escapes++;
                continue;
            }
            double r = ball.radius();
            double depth = r - Surfaces.walls(c.x(), c.y()).distance();
            for (Gizmo g : gizmos) {
                depth = Math.max(depth, r - Surfaces.nearest(g, c.x(), c.y()).distance());
            }
            for (int j = i + 1; j < balls.size(); j++) {
                BallState other = balls.get(j);
                if (!other.captured()) {
                    depth = Math.max(depth, r + other.radius() - Math.sqrt(c.distanceSquared(other.position())));
                }
            }
            if (depth > TOLERANCE) {
                tally.penetrations++;
                tally.deepest = Math.max(tally.deepest, depth);
            }
        }
    }
}
