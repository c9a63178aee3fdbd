package gizmoball.fuzz;

import java.util.List;

/**
 * The solid body of a gizmo as the fuzz checker sees it, in board coordinates, with its own distance arithmetic:
 * nothing here asks physics-lib or the model how far a point is from a shape, so a wrong contact in the game cannot
 * hide behind the same wrong geometry in the check.
 */
sealed interface Solid {

    /** Signed distance from (px, py) to the body: positive outside, negative inside (then minus the depth). */
    double signedDistance(double px, double py);

    /** The box that holds the body: min x, min y, max x, max y. */
    double[] bounds();

    /** A convex polygon with its corners in order (either way round). */
    record Polygon(List<Point> corners) implements Solid {
        public Polygon {
            corners = List.copyOf(corners);
        }

        @Override
        public double signedDistance(double px, double py) {
            double nearest = Double.POSITIVE_INFINITY;
            boolean inside = true;
            int n = corners.size();
            double orientation = orientation();
            for (int i = 0; i < n; i++) {
                Point a = corners.get(i);
                Point b = corners.get((i + 1) % n);
                nearest = Math.min(nearest, Point.distanceToSegment(px, py, a, b));
                double cross = (b.x() - a.x()) * (py - a.y()) - (b.y() - a.y()) * (px - a.x());
                if (cross * orientation < 0) {
                    inside = false;
                }
            }
            return inside ? -nearest : nearest;
        }

        /** Twice the signed area: its sign says which way round the corners go. */
        private double orientation() {
            double twiceArea = 0;
            for (int i = 0; i < corners.size(); i++) {
                Point a = corners.get(i);
                Point b = corners.get((i + 1) % corners.size());
                twiceArea += a.x() * b.y() - b.x() * a.y();
            }
            return twiceArea;
        }

        @Override
        public double[] bounds() {
            double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
                    Double.NEGATIVE_INFINITY};
            for (Point p : corners) {
                box[0] = Math.min(box[0], p.x());
                box[1] = Math.min(box[1], p.y());
                box[2] = Math.max(box[2], p.x());
                box[3] = Math.max(box[3], p.y());
            }
            return box;
        }
    }

    /** A disc. */
    record Disc(Point centre, double radius) implements Solid {
        @Override
        public double signedDistance(double px, double py) {
            return Math.hypot(px - centre.x(), py - centre.y()) - radius;
        }

        @Override
        public double[] bounds() {
            return new double[] {centre.x() - radius, centre.y() - radius, centre.x() + radius, centre.y() + radius};
        }
    }

    /** All points within {@code radius} of the segment from {@code a} to {@code b}: a flipper's bar. */
    record Capsule(Point a, Point b, double radius) implements Solid {
        @Override
        public double signedDistance(double px, double py) {
            return Point.distanceToSegment(px, py, a, b) - radius;
        }

        @Override
        public double[] bounds() {
            return new double[] {Math.min(a.x(), b.x()) - radius, Math.min(a.y(), b.y()) - radius,
                    Math.max(a.x(), b.x()) + radius, Math.max(a.y(), b.y()) + radius};
        }
    }
}
