package gizmoball.model.loop;

import physics.LineSegment;
import physics.Vect;

/**
 * The foot of the perpendicular from a point to a segment, as {@code Geometry.perpendicularPoint} finds it, reckoned
 * on the components (the same doubles, in the same order) into a place its user keeps: asking every face in reach of
 * a ball makes no vector.
 */
final class Foot {
    /** The foot last found. */
    double x;
    double y;

    /** Finds the foot from (px, py) on the segment; false, the foot unchanged, where it falls past an end. */
    boolean on(LineSegment segment, double px, double py) {
        Vect p1 = segment.p1();
        Vect p2 = segment.p2();
        double dirX = p2.x() - p1.x() + 0.0;
        double dirY = p2.y() - p1.y() + 0.0;
        if (dirX == 0 && dirY == 0) {
            x = p1.x();
            y = p1.y();
            return true;
        }
        // Measured from each end, as the library does, so that swapping the ends gives the same decision.
        double fromP1 = (px - p1.x() + 0.0) * dirX + (py - p1.y() + 0.0) * dirY;
        double fromP2 = (p2.x() - px + 0.0) * dirX + (p2.y() - py + 0.0) * dirY;
        if (fromP1 < 0 || fromP2 < 0) {
            return false;
        }
        double along = fromP1 / (dirX * dirX + dirY * dirY);
        x = p1.x() + (dirX * along + 0.0) + 0.0;
        y = p1.y() + (dirY * along + 0.0) + 0.0;
        return true;
    }
}
