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

    /**
     * Signed distance from p to a convex polygon whose sides are given in order round it (either orientation), each
     * from one corner to the next: a polygon gizmo's shape has them so, made once per placement.
     */
    static double toConvexPolygon(List<LineSegment> sides, Vect p) {
        double boundary = Double.POSITIVE_INFINITY;
        boolean inside = true;
        double orientation = 0;
        for (int i = 0; i < sides.size(); i++) {
            Vect a = sides.get(i).p1();
            Vect b = sides.get(i).p2();
            boundary = Math.min(boundary, distanceToSegment(sides.get(i), p));
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
