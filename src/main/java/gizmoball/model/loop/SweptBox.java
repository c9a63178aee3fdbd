package gizmoball.model.loop;

import physics.Circle;
import physics.LineSegment;
import physics.Vect;

/**
 * The box a ball sweeps in a window: its centre from where it is to where it is after the window, widened by its
 * radius and {@link Tolerances#REACH_MARGIN}. A segment or circle whose own box lies outside it cannot be
 * touched within the window, so detection asks physics-lib nothing about it: the margin, far above the rounding of
 * the library's times, keeps every contact it would find within the window inside the box. One per detector, set
 * again for every ball it asks about.
 */
final class SweptBox {
    double minX;
    double minY;
    double maxX;
    double maxY;

    /** The box of a ball at (x, y) moving at {@code velocity} for {@code window} seconds. */
    void set(double x, double y, double vx, double vy, double window) {
        // The doubles centre + velocity * window gives, as the ball's own move computes them.
        double toX = x + vx * window;
        double toY = y + vy * window;
        double reach = Arena.BALL_RADIUS + Tolerances.REACH_MARGIN;
        minX = Math.min(x, toX) - reach;
        minY = Math.min(y, toY) - reach;
        maxX = Math.max(x, toX) + reach;
        maxY = Math.max(y, toY) + reach;
    }

    /** Whether the segment lies wholly outside the box. */
    boolean misses(LineSegment segment) {
        Vect p1 = segment.p1();
        Vect p2 = segment.p2();
        return Math.max(p1.x(), p2.x()) < minX || Math.min(p1.x(), p2.x()) > maxX
                || Math.max(p1.y(), p2.y()) < minY || Math.min(p1.y(), p2.y()) > maxY;
    }

    /** Whether the circle lies wholly outside the box. */
    boolean misses(Circle circle) {
        Vect c = circle.getCenter();
        double r = circle.getRadius();
        return c.x() + r < minX || c.x() - r > maxX || c.y() + r < minY || c.y() - r > maxY;
    }
}
