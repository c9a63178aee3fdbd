package gizmoball.bench;

import gizmoball.model.Board;
import gizmoball.model.gizmo.BumperView;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.Gizmo;
import physics.Vect;

import java.util.List;

/**
 * Nearest-surface geometry from the gizmos' public shapes, written from the definitions and independent
 * of the model's collision code: the measuring instrument of {@link Probe} and the whole of the naive loop.
 */
final class Surfaces {

    /** Signed distance from a point to a solid (negative inside) and the unit normal pointing out of it there. */
    record Nearest(double distance, double nx, double ny) {
        static final Nearest FAR = new Nearest(Double.POSITIVE_INFINITY, 0, 0);
    }

    private Surfaces() {
    }

    /** Nearest point of a gizmo's solid; absorbers are not solids here (they capture on contact). */
    static Nearest nearest(Gizmo g, double px, double py) {
        if (g instanceof FlipperView f) {
            return fromSegment(f.pivot(), f.tip(), px, py, f.radius());
        }
        if (g instanceof BumperView b) {
            List<Vect> outline = b.outline();
            if (outline.isEmpty()) {
                Vect c = b.circle().getCenter();
                return fromPoint(c.x(), c.y(), px, py, b.circle().getRadius());
            }
            return fromConvexPolygon(outline, px, py);
        }
        return Nearest.FAR;
    }

    /** Distance from the point to the board's nearest outer wall (negative outside the board), normal inward. */
    static Nearest walls(double px, double py) {
        double size = Board.SIZE;
        Nearest best = new Nearest(px, 1, 0);
        if (size - px < best.distance()) {
            best = new Nearest(size - px, -1, 0);
        }
        if (py < best.distance()) {
            best = new Nearest(py, 0, 1);
        }
        if (size - py < best.distance()) {
            best = new Nearest(size - py, 0, -1);
        }
        return best;
    }

    private static Nearest fromPoint(double cx, double cy, double px, double py, double radius) {
        double dx = px - cx;
        double dy = py - cy;
        double d = Math.sqrt(dx * dx + dy * dy);
        return d == 0 ? new Nearest(-radius, 0, -1) : new Nearest(d - radius, dx / d, dy / d);
    }

    private static Nearest fromSegment(Vect a, Vect b, double px, double py, double radius) {
        double ex = b.x() - a.x();
        double ey = b.y() - a.y();
        double lengthSquared = ex * ex + ey * ey;
        double s = lengthSquared == 0 ? 0 : ((px - a.x()) * ex + (py - a.y()) * ey) / lengthSquared;
        s = Math.max(0, Math.min(1, s));
        return fromPoint(a.x() + s * ex, a.y() + s * ey, px, py, radius);
    }

    /** Convex polygon, either winding: outside, the nearest boundary point; inside, the nearest edge. */
    private static Nearest fromConvexPolygon(List<Vect> corners, double px, double py) {
        Nearest boundary = Nearest.FAR;
        int positive = 0;
        int negative = 0;
        for (int k = 0; k < corners.size(); k++) {
            Vect a = corners.get(k);
            Vect b = corners.get((k + 1) % corners.size());
            Nearest n = fromSegment(a, b, px, py, 0);
            if (n.distance() < boundary.distance()) {
                boundary = n;
            }
            double cross = (b.x() - a.x()) * (py - a.y()) - (b.y() - a.y()) * (px - a.x());
            if (cross > 0) {
                positive++;
            } else if (cross < 0) {
                negative++;
            }
        }
        boolean inside = positive == 0 || negative == 0;
        // Inside, the direction from the nearest boundary point to p points inward: flip it.
        return inside ? new Nearest(-boundary.distance(), -boundary.nx(), -boundary.ny()) : boundary;
    }
}
