package gizmoball.model.loop;

/**
 * When two balls touch, as {@code Geometry.timeUntilBallBallCollision} gives it for their circles (radius
 * {@link Arena#BALL_RADIUS}) and velocities, reckoned on the components: the very double, without the centres, circles
 * and velocities the call takes. The JIT keeps the centre vectors made for it, inside their circles, and they were a
 * third of what a tick of the 100-ball peer board allocated (docs/design.md, "What a tick allocates").
 */
final class BallMeeting {
    private static final double TOUCH = 2 * Arena.BALL_RADIUS;

    private BallMeeting() {
    }

    /**
     * Seconds until a ball whose centre lies (dx, dy) from another's, moving at (ux, uy) relative to it, touches it:
     * infinite if never, 0 if they touch or overlap now and close. Each is the difference of two components as a
     * {@code Vect} holds them.
     */
    static double time(double dx, double dy, double ux, double uy) {
        // The API's closed form for |d + u t| = 2r: (|d| - 2r)(|d| + 2r) for |d|^2 - (2r)^2, Lagrange's identity for the
        // discriminant, and the root without cancellation.
        double along = dx * ux + dy * uy;
        if (!(along < 0)) {
            return Double.POSITIVE_INFINITY;   // not closing: never, whether apart, touching or overlapping
        }
        double length = norm(dx, dy);
        double excess = (length - TOUCH) * (length + TOUCH);
        if (excess <= 0) {
            return 0;
        }
        double cross = Math.abs(dx * uy - dy * ux);
        double reach = norm(ux, uy) * TOUCH;
        double discriminant = (reach - cross) * (reach + cross);
        if (discriminant < 0) {
            return Double.POSITIVE_INFINITY;
        }
        return excess / (-along + Math.sqrt(discriminant));
    }

    /** |(x, y)| as the API takes it here: the square root of the sum of squares, hypot where they under- or overflow. */
    private static double norm(double x, double y) {
        double sumOfSquares = x * x + y * y;
        if (sumOfSquares < Double.MIN_NORMAL || sumOfSquares == Double.POSITIVE_INFINITY) {
            return StrictMath.hypot(x, y);
        }
        return Math.sqrt(sumOfSquares);
    }
}
