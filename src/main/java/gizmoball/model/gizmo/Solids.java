package gizmoball.model.gizmo;

import java.util.List;

import physics.Geometry;
import physics.LineSegment;
import physics.Vect;

/**
 * Signed distances from a point to the solid bodies of gizmos (negative inside), behind each gizmo's
 * {@code signedDistance}: the board refuses overlapping placements and checks its invariants with them; collisions
 * never use this, they go through physics.Geometry.
 */
final class Solids {
    private Solids() {
    }

    /** Distance from p to the segment, through the library's perpendicular foot or the nearer end. */
    static double distanceToSegment(LineSegment segment, Vect p) {
        Vect foot = Geometry.perpendicularPoint(segment, p);
        if (foot != null) {
            return Math.sqrt(Geometry.distanceSquared(foot, p));
        }
        return Math.sqrt(Math.min(Geometry.distanceSquared(segment.p1(), p), Geometry.distanceSquared(segment.p2(), p)));
    }

    /** Signed distance from p to a convex polygon whose corners are given in order (either orientation). */
    static double toConvexPolygon(List<Vect> corners, Vect p) {
        double boundary = Double.POSITIVE_INFINITY;
        boolean inside = true;
        double orientation = 0;
        for (int i = 0; i < corners.size(); i++) {
            Vect a = corners.get(i);
            Vect b = corners.get((i + 1) % corners.size());
            boundary = Math.min(boundary, distanceToSegment(new LineSegment(a, b), p));
            double cross = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
            if (cross != 0) {
                if (orientation == 0) {
                    orientation = Math.signum(cross);
                } else if (Math.signum(cross) != orientation) {
                    inside = false;
                }
            }
        }
        return inside ? -boundary : boundary;
    }

    /** Signed distance from p to a capsule: all points within radius of the segment from a to b. */
    static double toCapsule(LineSegment core, double radius, Vect p) {
        return distanceToSegment(core, p) - radius;
    }

    static double toDisc(Vect centre, double radius, Vect p) {
        return Math.sqrt(Geometry.distanceSquared(centre, p)) - radius;
    }
}
