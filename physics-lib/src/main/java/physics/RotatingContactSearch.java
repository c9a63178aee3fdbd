package physics;

/**
 * Earliest contact of a moving ball with an obstacle turning about a pivot: the face of a segment [a, b] (the
 * meaning of {@link GeometryImpl#timeUntilWallCollision}, turning), or a circle. Written from the following
 * mathematics. The face searched is closed; the static face's half-open end b differs from it only for a contact
 * whose foot lands exactly on b, which a turning segment meets with probability zero.
 * <p>
 * <b>Frame.</b> The obstacle at time t is the initial one turned by w t about the pivot p, so the ball centre
 * c0 + v t meets it exactly when q(t) = p + R(-w t) u(t), u(t) = c0 + v t - p, meets the initial obstacle. In that
 * frame the obstacle is still and only q moves.
 * <p>
 * <b>Where the centre may not go.</b> For a circle of radius R and ball radius r: the disc of radius R + r. For a
 * segment's face: the rectangle F of the points whose foot lies on the segment and whose distance x from its line
 * is at most r. The ball touches the face when q enters F through one of its long sides (|x| = r, ends included);
 * q entering F through a short side is the ball running into an end, which belongs to a zero-radius circle there.
 * The gap g(t) is the distance from q(t) to the disc or to F; both are convex sets.
 * <p>
 * <b>Bounds.</b> q'(t) = R(-wt) v - w J R(-wt) u and q''(t) = -2 w J R(-wt) v - w&sup2; R(-wt) u (J: quarter
 * turn), so |q'| &le; |v| + |w| |u| and |q''| &le; 2 |w| |v| + w&sup2; |u|. |u(t)| is convex in t, so on a slice of
 * the window its maximum is at a slice end: that gives per-slice constants L and M.
 * <p>
 * <b>Safe steps.</b> The distance to a convex set is convex with a unit gradient n, so
 * g(s) &ge; g(t) + n&middot;(q(s) - q(t)) &ge; g(t) + g'(t)(s - t) - M (s - t)&sup2;/2, and also
 * g(s) &ge; g(t) - L (s - t).
 * Stepping to the first zero of the larger of these lower bounds can never step over a contact, and near a
 * contact the step is a Newton step on a bound from below, so it converges fast and from the safe side. The
 * search stops when the gap is within {@link #CONTACT_TOLERANCE} while closing.
 * <p>
 * <b>Through an end.</b> After q has come to F's short side, the ball overlaps the end, and no face contact can
 * happen while |x| &lt; r: a face contact needs |x| to come down through r. The search moves on by steps over
 * which |x| cannot reach r: x is linear in q, so &plusmn;x(s) &le; &plusmn;(x(t) + x'(t)(s - t)) + M (s - t)&sup2;/2
 * and |x(s)| &le; |x(t)| + L (s - t). Once |x| is back at r it carries on as above.
 * <p>
 * <b>Already in contact.</b> Touching or overlapping the face (or the circle) and closing is time 0. Closing is
 * decided to second order: the gap's mean rate over the next touching step (below) is negative. So a contact that
 * begins touching with zero closing speed and then closes, as when a flipper's side takes a ball over from its
 * round end, is a contact at that moment, and one that only grazes and leaves is none. While the ball touches or
 * overlaps without closing, the search moves on by touching steps, over which the gap cannot drop by more than
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

    /** Where q is, for the search: what may happen next and how far it may step. */
    private enum Region {
        /** More than the tolerance away from the forbidden set: safe steps. */
        CLEAR,
        /** Touching or overlapping the face or circle: a contact if closing. */
        TOUCHING,
        /** A wall only: in the band |x| &lt; r, come in over an end: no face contact until |x| is back at r. */
        THROUGH_END
    }

    /**
     * Each thread's search, set afresh by {@link #start} for every question: a flipper's swing asks one for each part in
     * reach of each ball, every tick, and a new search each time was much of what a tick allocated.
     */
    private static final ThreadLocal<RotatingContactSearch> SEARCH =
            ThreadLocal.withInitial(RotatingContactSearch::new);

    private boolean wall;
    private double ax;
    private double ay;
    /** Wall: unit vector from a to b, and the segment's length. */
    private double alongX;
    private double alongY;
    private double length;
    /** Wall: the ball's radius; circle: the sum of the radii. */
    private double contactDistance;
    private Vect pivot;
    private double w;
    /** c0 - pivot, as {@code Vect.minus} would hold it. */
    private double c0MinusPivotX;
    private double c0MinusPivotY;
    private Vect v;

    /** Distance from q to the forbidden set (0 inside it) and its rate. */
    private double gap;
    private double gapRate;
    /**
     * Wall: |x| - r; circle: the gap (negative when overlapping). Its rate (a centre on the line moves away) and its
     * second derivative, which decides a contact that touches at zero closing speed.
     */
    private double faceGap;
    private double faceRate;
    private double faceAcceleration;
    /** Wall: the signed distance x of q from the line, its rate, and how far q's foot lies beyond the segment. */
    private double offset;
    private double offsetRate;
    private double beyond;

    private RotatingContactSearch() {
    }

    /** This thread's search, set for the obstacle and the ball. */
    private static RotatingContactSearch start(boolean wall, Vect a, Vect b, double contactDistance, Vect pivot,
                                               double angularVelocity, Circle ball, Vect velocity) {
        return SEARCH.get().set(wall, a, b, contactDistance, pivot, angularVelocity, ball, velocity);
    }

    private RotatingContactSearch set(boolean wall, Vect a, Vect b, double contactDistance, Vect pivot,
                                      double angularVelocity, Circle ball, Vect velocity) {
        this.wall = wall;
        this.ax = a.x();
        this.ay = a.y();
        this.length = Math.sqrt(a.distanceSquared(b));
        this.alongX = wall ? (b.x() - a.x()) / length : 0;
        this.alongY = wall ? (b.y() - a.y()) / length : 0;
        this.contactDistance = contactDistance;
        this.pivot = pivot;
        this.w = angularVelocity;
        this.c0MinusPivotX = ball.getCenter().x() - pivot.x() + 0.0;
        this.c0MinusPivotY = ball.getCenter().y() - pivot.y() + 0.0;
        this.v = velocity;
        return this;
    }

    /**
     * The earliest time in [0, foresight] at which the ball touches the face of the segment [a, b] while closing,
     * or infinity. Contacts with the segment beyond its ends are not face contacts.
     */
    static double firstFaceContact(LineSegment segment, Vect pivot, double angularVelocity, Circle ball,
                                   Vect velocity, double foresight, int slices) {
        return start(true, segment.p1(), segment.p2(), ball.getRadius(), pivot, angularVelocity, ball, velocity)
                .search(foresight, slices,
                        Math.max(pivot.distanceSquared(segment.p1()), pivot.distanceSquared(segment.p2())));
    }

    /** The earliest time in [0, foresight] at which the ball touches the circle while closing, or infinity. */
    static double firstCircleContact(Circle circle, Vect pivot, double angularVelocity, Circle ball, Vect velocity,
                                     double foresight, int slices) {
        Vect centre = circle.getCenter();
        return start(false, centre, centre, circle.getRadius() + ball.getRadius(), pivot, angularVelocity, ball,
                velocity).search(foresight, slices, pivot.distanceSquared(centre));
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
        // |u| at the slice's start: a slice the loop leaves without returning ends with t = sliceEnd exactly, so the
        // next one starts where this one's end was measured (one hypot a slice, not two)
        double fromPivotAtT = fromPivot(t);
        if (gap - (speed + spin * Math.max(fromPivotAtT, fromPivot(foresight))) * foresight > 2 * CONTACT_TOLERANCE) {
            // The gap cannot close to the tolerance within the window (its rate is at most L over all of it, twice
            // the tolerance leaving room for the rounding of the gaps the slices would measure): the search would
            // step through every slice clear of the obstacle, as most searches about a ball near a swinging flipper
            // do, each slice a rotation and a hypot.
            return Double.POSITIVE_INFINITY;
        }
        Region region = classify(null, 0);
        for (int slice = 0, steps = 0; slice < slices; slice++) {
            double sliceEnd = slice == slices - 1 ? foresight : foresight * (slice + 1) / slices;
            double fromPivotAtEnd = fromPivot(sliceEnd);
            double farthest = Math.max(fromPivotAtT, fromPivotAtEnd);
            double lipschitz = speed + spin * farthest;
            double curvature = 2 * spin * speed + w * w * farthest;
            while (true) {
                if (region == Region.TOUCHING && closing(curvature)) {
                    return t;
                }
                if (t >= sliceEnd) {
                    break;
                }
                if (++steps > MAX_STEPS) {
                    return t;
                }
                if (region == Region.TOUCHING && curvature == 0) {
                    return Double.POSITIVE_INFINITY; // straight motion, not closing: the convex gap only grows
                }
                t = Math.min(t + step(region, lipschitz, curvature), sliceEnd);
                double beyondBefore = beyond;
                evaluate(t);
                region = classify(region, beyondBefore);
            }
            fromPivotAtT = fromPivotAtEnd;
        }
        return Double.POSITIVE_INFINITY;
    }

    /** A step over which nothing can happen that the region does not allow for (see the class comment). */
    private double step(Region region, double lipschitz, double curvature) {
        return switch (region) {
            case CLEAR -> Math.max(gap / lipschitz, firstZero(gap, gapRate, curvature));
            case TOUCHING -> touchingStep(curvature);
            case THROUGH_END -> Math.max(-faceGap / lipschitz,
                    Math.min(firstZero(contactDistance - offset, -offsetRate, curvature),
                            firstZero(contactDistance + offset, offsetRate, curvature)));
        };
    }

    /** Where faceGap + faceRate h - curvature h&sup2;/2 is CONTACT_TOLERANCE below faceGap. */
    private double touchingStep(double curvature) {
        return (faceRate + Math.sqrt(faceRate * faceRate + 2 * curvature * CONTACT_TOLERANCE)) / curvature;
    }

    /**
     * Whether the touching ball closes on the obstacle now, at a rate that the next touching step h resolves: the
     * gap's rate is below -|faceAcceleration| h / 2, the most the second-order term can change the gap's mean rate
     * over that step. A contact whose rate is above that is grazing and is not reported yet. One that approaches by
     * a rounding's worth of a rate and is turned around within the step is then no contact (reported, a reflection
     * would send a ball that is leaving back in). One that touches at zero closing speed and is then closed on (the
     * side of a flipper taking a ball over from its round end, a surface turning into a ball that slides along it)
     * is reported within a touching step or two, about 1e-10 L deep at most, with a closing speed for a reflection to
     * act on. Reported at the instant of zero closing speed, a caller that reflects and asks again would get the
     * same contact at time 0, without end. Without curvature the motion is straight and the convex gap closes only
     * if its rate is negative.
     */
    private boolean closing(double curvature) {
        if (curvature == 0) {
            return faceRate < 0;
        }
        return faceRate < -Math.abs(faceAcceleration) * touchingStep(curvature) / 2;
    }

    /**
     * The region q is in now, given the region it was in at the previous evaluation (null at time 0) and how far
     * its foot was beyond the ends then. Overlapping the face counts as touching it only if the ball got there
     * over the face or was there at time 0. A safe step from clear lands on the boundary of the face rectangle,
     * so it came in over an end only if its foot was beyond one before; judging by that, rounding that puts the
     * landing point a little inside cannot turn a face contact into an end one.
     */
    private Region classify(Region previous, double beyondBefore) {
        if (gap > CONTACT_TOLERANCE) {
            return Region.CLEAR;
        }
        if (!wall || faceGap >= -CONTACT_TOLERANCE) {
            return Region.TOUCHING;
        }
        if (previous == null) {
            return beyond > 0 ? Region.THROUGH_END : Region.TOUCHING;
        }
        return switch (previous) {
            case CLEAR -> beyondBefore > CONTACT_TOLERANCE ? Region.THROUGH_END : Region.TOUCHING;
            case TOUCHING -> beyond > 0 ? Region.THROUGH_END : Region.TOUCHING;
            case THROUGH_END -> Region.THROUGH_END;
        };
    }

    /**
     * The first positive zero of value + rate h - curvature h&sup2;/2 for value &ge; 0, in a form without
     * cancellation; infinity if there is none.
     */
    private static double firstZero(double value, double rate, double curvature) {
        double root = Math.sqrt(rate * rate + 2 * curvature * value);
        if (rate < 0) {
            return 2 * value / (root - rate);
        }
        return curvature == 0 ? Double.POSITIVE_INFINITY : (rate + root) / curvature;
    }

    /** min over [0, foresight] of |c0 + v t - pivot|, the ball centre's distance from the pivot (frame-free). */
    private double closestApproachToPivot(double foresight) {
        double speedSquared = v.dot(v);
        double tClosest = speedSquared == 0 ? 0 : -(c0MinusPivotX * v.x() + c0MinusPivotY * v.y()) / speedSquared;
        return fromPivot(Math.max(0, Math.min(foresight, tClosest)));
    }

    /** |u(t)| = |c0 + v t - pivot|, made of no vector (the search asks for it at every slice). */
    private double fromPivot(double t) {
        return ClosedForms.length(c0MinusPivotX + v.x() * t, c0MinusPivotY + v.y() * t);
    }

    /** Sets the gaps and rates at time t in the obstacle's frame (plain arithmetic: this is the hot loop). */
    private void evaluate(double t) {
        double cos = StrictMath.cos(w * t);
        double sin = -StrictMath.sin(w * t); // R(-w t), the same on every JVM and processor
        double ux = c0MinusPivotX + v.x() * t;
        double uy = c0MinusPivotY + v.y() * t;
        double turnedX = ux * cos - uy * sin;
        double turnedY = ux * sin + uy * cos;
        double relX = pivot.x() + turnedX - ax;
        double relY = pivot.y() + turnedY - ay;
        // q' = R(-wt) v - w J R(-wt) u and q'' = -2 w J R(-wt) v - w^2 R(-wt) u, with J (x, y) = (-y, x)
        double turnedVX = v.x() * cos - v.y() * sin;
        double turnedVY = v.x() * sin + v.y() * cos;
        double rateX = turnedVX + w * turnedY;
        double rateY = turnedVY - w * turnedX;
        double accelerationX = 2 * w * turnedVY - w * w * turnedX;
        double accelerationY = -2 * w * turnedVX - w * w * turnedY;
        if (wall) {
            evaluateFace(relX, relY, rateX, rateY, accelerationX, accelerationY);
        } else {
            double distance = StrictMath.hypot(relX, relY);
            gap = distance - contactDistance;
            faceGap = gap;
            if (distance == 0) {
                // At the centre itself the direction is undefined; "not closing" lets the search move on.
                gapRate = 0;
                faceAcceleration = 0;
            } else {
                gapRate = (relX * rateX + relY * rateY) / distance;
                // |q - c|'' = (|q'|^2 - |q - c|'^2) / |q - c| + n . q''
                faceAcceleration = (rateX * rateX + rateY * rateY - gapRate * gapRate) / distance
                        + (relX * accelerationX + relY * accelerationY) / distance;
            }
            faceRate = gapRate;
        }
    }

    /** The face's gaps from q - a, q' and q''. */
    private void evaluateFace(double relX, double relY, double rateX, double rateY, double accelerationX,
                              double accelerationY) {
        double along = relX * alongX + relY * alongY;
        double alongRate = rateX * alongX + rateY * alongY;
        offset = relY * alongX - relX * alongY; // along the normal (-alongY, alongX)
        offsetRate = rateY * alongX - rateX * alongY;
        double beyondRate;
        if (along < 0) {
            beyond = -along;
            beyondRate = -alongRate;
        } else if (along > length) {
            beyond = along - length;
            beyondRate = alongRate;
        } else {
            beyond = 0;
            beyondRate = 0;
        }
        faceGap = Math.abs(offset) - contactDistance;
        faceRate = offset == 0 ? Math.abs(offsetRate) : Math.signum(offset) * offsetRate;
        double offsetAcceleration = accelerationY * alongX - accelerationX * alongY;
        // |x|'' is sign(x) x''; on the line it is the sign of the way the centre leaves it (of x', else of x'').
        double side = offset != 0 ? Math.signum(offset) : offsetRate != 0 ? Math.signum(offsetRate)
                : Math.signum(offsetAcceleration);
        faceAcceleration = side * offsetAcceleration;
        double out = Math.max(faceGap, 0);
        gap = StrictMath.hypot(beyond, out);
        gapRate = gap == 0 ? 0 : (beyond * beyondRate + out * faceRate) / gap;
    }
}
