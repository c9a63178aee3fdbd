package gizmoball.fuzz;

/** A point of the board in L, with the few sums the checker's geometry needs. */
record Point(double x, double y) {

    double distanceTo(Point other) {
        return Math.hypot(x - other.x, y - other.y);
    }

    /** Distance from (px, py) to the closed segment ab (to a itself when a and b coincide). */
    static double distanceToSegment(double px, double py, Point a, Point b) {
        double dx = b.x - a.x;
        double dy = b.y - a.y;
        double lengthSquared = dx * dx + dy * dy;
        double t = lengthSquared == 0 ? 0 : ((px - a.x) * dx + (py - a.y) * dy) / lengthSquared;
        t = Math.max(0, Math.min(1, t));
        return Math.hypot(px - (a.x + t * dx), py - (a.y + t * dy));
    }
}
