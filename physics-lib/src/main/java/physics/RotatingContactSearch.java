package physics;

/**
 * Earliest contact of a moving ball with an obstacle turning about a pivot: a closed segment [a, b] thickened by
 * a radius (a = b is a circle). Written from the following mathematics.
 * <p>
 * <b>Frame.</b> The obstacle at time t is the initial one turned by w t about the pivot p, so the distance from
 * the ball centre c0 + v t to it equals the distance from q(t) = p + R(-w t) u(t), u(t) = c0 + v t - p, to the
 * initial obstacle. In that frame the obstacle is still and only q moves. The gap is
 * g(t) = dist(q(t), [a, b]) - (obstacle radius + ball radius).
 * <p>
 * <b>Bounds.</b> q'(t) = R(-wt) v - w J R(-wt) u and q''(t) = -2 w J R(-wt) v - w&sup2; R(-wt) u (J: quarter
 * turn), so |q'| &le; |v| + |w| |u| and |q''| &le; 2 |w| |v| + w&sup2; |u|. |u(t)| is convex in t, so on a slice of
 * the window its maximum is at a slice end: that gives per-slice constants L and M.
 * <p>
 * <b>Safe steps.</b> The distance to a convex set is convex with a unit gradient n, so
 * g(s) &ge; g(t) + n&middot;(q(s) - q(t)) &ge; g(t) + g'(t)(s - t) - M (s - t)&sup2;/2, and also g(s) &ge; g(t) - L (s - t).
 * Stepping to the first zero of the larger of these lower bounds can never step over a contact, wherever on
 * the segment (ends included) it happens, and near a contact the step is a Newton step on a bound from below,
 * so it converges fast and from the safe side. The search stops when the gap is within
 * {@link #CONTACT_TOLERANCE} while closing (g' &lt; 0).
 * <p>
 * <b>Already in contact.</b> Touching or overlapping and closing is time 0. While the ball touches or overlaps
 * without closing, the search moves on by steps over which the gap cannot drop by more than
 * {@link #CONTACT_TOLERANCE}, until the ball is clear again or starts closing.
 */
final class RotatingContactSearch {
    /** The reported contact has a gap in [0, CONTACT_TOLERANCE] (in L) unless it is already closing at 0. */
    static final double CONTACT_TOLERANCE = 1e-10;
    /**
     * A guard against pathological near-tangent cases; far above what any test or game case needs (a few
     * hundred). When reached, the current time, which is still safely before any contact, is returned.
     */
    private static final int MAX_STEPS = 200_000;

    private final Vect a;
    private final Vect ab;
    private final double abLengthSquared;
    private final double contactDistance;
    private final Vect pivot;
    private final double w;
    private final Vect c0MinusPivot;
    private final Vect v;

    private double gap;
    private double gapRate;

    private RotatingContactSearch(Vect a, Vect b, double obstacleRadius, Vect pivot, double angularVelocity,
                                  Circle ball, Vect velocity) {
        if (!Double.isFinite(angularVelocity)) {
            throw new IllegalArgumentException("angular velocity must be finite, got " + angularVelocity);
        }
        this.a = a;
        this.ab = b.minus(a);
        this.abLengthSquared = ab.dot(ab);
        this.contactDistance = obstacleRadius + ball.getRadius();
        this.pivot = pivot;
        this.w = angularVelocity;
        this.c0MinusPivot = ball.getCenter().minus(pivot);
        this.v = velocity;
    }

    /**
     * The earliest time in [0, foresight] at which the ball touches the obstacle while closing, or infinity.
     *
     * @param a              one end of the obstacle's core segment at time 0
     * @param b              the other end (equal to a for a circle)
     * @param obstacleRadius the thickness around the core segment (the circle's radius; 0 for a wall)
     */
    static double firstContact(Vect a, Vect b, double obstacleRadius, Vect pivot, double angularVelocity,
                               Circle ball, Vect velocity, double foresight, int slices) {
        return new RotatingContactSearch(a, b, obstacleRadius, pivot, angularVelocity, ball, velocity)
                .search(foresight, slices, Math.max(pivot.distanceSquared(a), pivot.distanceSquared(b)));
    }

    private double search(double foresight, int slices, double farthestCoreSquared) {
        double reach = Math.sqrt(farthestCoreSquared) + contactDistance;
        if (closestApproachToPivot(foresight) > reach + CONTACT_TOLERANCE) {
            return Double.POSITIVE_INFINITY; // the obstacle sweeps a disc the ball never enters
        }
        double speed = v.length();
        double spin = Math.abs(w);
        double t = 0;
        evaluate(t);
        for (int slice = 0, steps = 0; slice < slices; slice++) {
            double sliceEnd = slice == slices - 1 ? foresight : foresight * (slice + 1) / slices;
            double farthest = Math.max(u(t).length(), u(sliceEnd).length());
            double lipschitz = speed + spin * farthest;
            double curvature = 2 * spin * speed + w * w * farthest;
            while (t < sliceEnd) {
                if (++steps > MAX_STEPS) {
                    return t;
                }
                double step;
                if (gap <= CONTACT_TOLERANCE) {
                    if (gapRate < 0) {
                        return t;
                    }
                    if (curvature == 0) {
                        return Double.POSITIVE_INFINITY; // straight motion, not closing: the convex gap only grows
                    }
                    // Where gap + gapRate h - curvature h^2 / 2 is CONTACT_TOLERANCE below the current gap.
                    step = (gapRate + Math.sqrt(gapRate * gapRate + 2 * curvature * CONTACT_TOLERANCE)) / curvature;
                } else {
                    step = Math.max(gap / lipschitz, quadraticBoundStep(curvature));
                }
                t = Math.min(t + step, sliceEnd);
                evaluate(t);
            }
        }
        return gap <= CONTACT_TOLERANCE && gapRate < 0 ? t : Double.POSITIVE_INFINITY;
    }

    /** The first positive zero of gap + gapRate h - curvature h&sup2;/2, in a form without cancellation. */
    private double quadraticBoundStep(double curvature) {
        double root = Math.sqrt(gapRate * gapRate + 2 * curvature * gap);
        if (gapRate < 0) {
            return 2 * gap / (root - gapRate);
        }
        return curvature == 0 ? Double.POSITIVE_INFINITY : (gapRate + root) / curvature;
    }

    /** min over [0, foresight] of |c0 + v t - pivot|, the ball centre's distance from the pivot (frame-free). */
    private double closestApproachToPivot(double foresight) {
        double speedSquared = v.dot(v);
        double tClosest = speedSquared == 0 ? 0 : -c0MinusPivot.dot(v) / speedSquared;
        return u(Math.max(0, Math.min(foresight, tClosest))).length();
    }

    private Vect u(double t) {
        return c0MinusPivot.plus(v.times(t));
    }

    /** Sets gap and gapRate to g(t) and g'(t) in the obstacle's frame (plain arithmetic: this is the hot loop). */
    private void evaluate(double t) {
        double cos = Math.cos(w * t);
        double sin = -Math.sin(w * t); // R(-w t)
        double ux = c0MinusPivot.x() + v.x() * t;
        double uy = c0MinusPivot.y() + v.y() * t;
        double turnedX = ux * cos - uy * sin;
        double turnedY = ux * sin + uy * cos;
        double qx = pivot.x() + turnedX;
        double qy = pivot.y() + turnedY;
        // q' = R(-wt) v - w J R(-wt) u, with J (x, y) = (-y, x)
        double rateX = v.x() * cos - v.y() * sin + w * turnedY;
        double rateY = v.x() * sin + v.y() * cos - w * turnedX;
        double s = abLengthSquared == 0 ? 0
                : Math.max(0, Math.min(1, ((qx - a.x()) * ab.x() + (qy - a.y()) * ab.y()) / abLengthSquared));
        double offsetX = qx - a.x() - s * ab.x();
        double offsetY = qy - a.y() - s * ab.y();
        double distance = Math.hypot(offsetX, offsetY);
        gap = distance - contactDistance;
        // On the core itself the direction is undefined; treating it as "not closing" lets the search move on.
        gapRate = distance == 0 ? 0 : (offsetX * rateX + offsetY * rateY) / distance;
    }
}
