package gizmoball.model.loop;

/**
 * Two balls of equal mass after an elastic bounce at their centres now, as {@code Geometry.reflectBalls} with masses
 * 1 and 1 gives them, reckoned on the components: the very doubles its two vectors would hold, without making them.
 * The API's vectors were a fifth of what a tick of the 100-ball peer board allocated, and the JIT keeps them however
 * the call is inlined (docs/design.md, "What a tick allocates"). Kept by its user, set afresh for each bounce.
 */
final class BallBounce {
    /** The first ball's velocity after the bounce. */
    double firstX;
    double firstY;
    /** The second ball's. */
    double secondX;
    double secondY;

    /**
     * The bounce of a ball at (x1, y1) moving at (vx1, vy1) with one at (x2, y2) moving at (vx2, vy2), each component
     * as a {@code Vect} holds it (-0 as +0). Where there is no normal (coinciding centres) the velocities stay.
     */
    void between(double x1, double y1, double vx1, double vy1, double x2, double y2, double vx2, double vy2) {
        double dx = x2 - x1;
        double dy = y2 - y1;
        double dd = dx * dx + dy * dy;
        if (dd < Double.MIN_NORMAL || dd == Double.POSITIVE_INFINITY) {
            double scale = Math.max(Math.abs(dx), Math.abs(dy));   // the API's rescaling of a tiny or huge offset
            dx /= scale;
            dy /= scale;
            dd = dx * dx + dy * dy;
        }
        // The normal part of the relative velocity, along the offset; with equal masses each ball takes all of it
        // (the API's 2 / (1 + m1 / m2) is exactly 1).
        double approach = ((vx1 - vx2) * dx + (vy1 - vy2) * dy) / dd;
        if (Double.isNaN(approach)) {
            firstX = vx1;
            firstY = vy1;
            secondX = vx2;
            secondY = vy2;
            return;
        }
        firstX = vx1 - dx * approach + 0.0;
        firstY = vy1 - dy * approach + 0.0;
        secondX = vx2 + dx * approach + 0.0;
        secondY = vy2 + dy * approach + 0.0;
    }
}
