package gizmoball.bench;

import gizmoball.model.Ball;
import gizmoball.model.Board;
import gizmoball.model.Bumper;
import gizmoball.model.Flipper;
import gizmoball.model.Gizmo;
import physics.Vect;

import java.util.List;

/**
 * Counts what must never happen, from the balls' positions and the gizmos' shapes alone (independently of
 * the model's own collision code and of the wording of its messages): a non-finite ball state, a ball
 * whose centre has left the board (escape), and a ball inside a wall, a bumper, a flipper or another ball
 * by more than {@link #TOLERANCE} (penetration). Captured balls sit inside their absorber by design and
 * are skipped; absorbers capture on contact and so are not obstacles here.
 */
public final class Probe {

    public static final double TOLERANCE = 1e-6;

    /** Counts over a run: ball-ticks with each kind of fault, and the deepest penetration seen. */
    public static final class Tally {
        long nonFinite;
        long escapes;
        long penetrations;
        double deepest;

        void add(Tally other) {
            nonFinite += other.nonFinite;
            escapes += other.escapes;
            penetrations += other.penetrations;
            deepest = Math.max(deepest, other.deepest);
        }

        boolean clean() {
            return nonFinite == 0 && escapes == 0 && penetrations == 0;
        }
    }

    private Probe() {
    }

    /** Adds this board's current faults to the tally. */
    public static void check(Board board, Tally tally) {
        List<Ball> balls = board.balls();
        for (int i = 0; i < balls.size(); i++) {
            Ball ball = balls.get(i);
            if (ball.isCaptured()) {
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
            double depth = r - Math.min(Math.min(c.x(), Board.SIZE - c.x()), Math.min(c.y(), Board.SIZE - c.y()));
            for (Gizmo g : board.gizmos()) {
                depth = Math.max(depth, r - distance(g, c));
            }
            for (int j = i + 1; j < balls.size(); j++) {
                Ball other = balls.get(j);
                if (!other.isCaptured()) {
                    depth = Math.max(depth, r + other.radius() - length(c.x() - other.position().x(), c.y() - other.position().y()));
                }
            }
            if (depth > TOLERANCE) {
                tally.penetrations++;
                tally.deepest = Math.max(tally.deepest, depth);
            }
        }
    }

    /** Signed distance from a point to a gizmo's solid shape: negative inside. Absorbers: +infinity. */
    static double distance(Gizmo g, Vect p) {
        if (g instanceof Flipper f) {
            return segmentDistance(f.pivot(), f.tip(), p) - f.radius();
        }
        if (g instanceof Bumper b) {
            List<Vect> outline = b.outline();
            if (outline.isEmpty()) {
                Vect centre = b.circle().getCenter();
                return length(p.x() - centre.x(), p.y() - centre.y()) - b.circle().getRadius();
            }
            return polygonDistance(outline, p);
        }
        return Double.POSITIVE_INFINITY;
    }

    /** Signed distance to a convex polygon (either winding). */
    static double polygonDistance(List<Vect> corners, Vect p) {
        double nearest = Double.POSITIVE_INFINITY;
        int positive = 0;
        int negative = 0;
        for (int k = 0; k < corners.size(); k++) {
            Vect a = corners.get(k);
            Vect b = corners.get((k + 1) % corners.size());
            nearest = Math.min(nearest, segmentDistance(a, b, p));
            double cross = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
            if (cross > 0) {
                positive++;
            } else if (cross < 0) {
                negative++;
            }
        }
        boolean inside = positive == 0 || negative == 0;
        return inside ? -nearest : nearest;
    }

    static double segmentDistance(Vect a, Vect b, Vect p) {
        double ex = b.x() - a.x();
        double ey = b.y() - a.y();
        double lengthSquared = ex * ex + ey * ey;
        double s = lengthSquared == 0 ? 0 : ((p.x() - a.x()) * ex + (p.y() - a.y()) * ey) / lengthSquared;
        s = Math.max(0, Math.min(1, s));
        return length(p.x() - a.x() - s * ex, p.y() - a.y() - s * ey);
    }

    private static double length(double x, double y) {
        return Math.sqrt(x * x + y * y);
    }
}
