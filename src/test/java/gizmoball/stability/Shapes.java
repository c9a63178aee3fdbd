package gizmoball.stability;

import physics.Vect;

/** Independent distances for the tests' own checks (the model's Invariants are checked separately). */
final class Shapes {

    private Shapes() {
    }

    /** Distance from p to the segment ab. */
    static double toSegment(Vect a, Vect b, Vect p) {
        double ex = b.x() - a.x();
        double ey = b.y() - a.y();
        double lengthSquared = ex * ex + ey * ey;
        double s = lengthSquared == 0 ? 0 : ((p.x() - a.x()) * ex + (p.y() - a.y()) * ey) / lengthSquared;
        s = Math.max(0, Math.min(1, s));
        return Math.hypot(p.x() - a.x() - s * ex, p.y() - a.y() - s * ey);
    }
}
