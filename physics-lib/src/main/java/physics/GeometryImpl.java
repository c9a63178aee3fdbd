package physics;

import static physics.ClosedForms.excessSquared;
import static physics.ClosedForms.footOnFace;
import static physics.ClosedForms.length;
import static physics.ClosedForms.quarterDiscriminant;
import static physics.ClosedForms.reflectAlong;
import static physics.ClosedForms.reflectOffMovingSurface;
import static physics.ClosedForms.timeUntilCentresAt;
import static physics.ClosedForms.timeUntilFace;

import physics.Geometry.DoublePair;
import physics.Geometry.VectPair;

/**
 * The collision geometry, written from the mathematics. Immutable and stateless apart from its two tuning
 * parameters, so one instance can be shared between threads.
 * <p>
 * Conventions: times in seconds, {@code Double.POSITIVE_INFINITY} for "no collision"; angles and angular
 * velocities (rad/s) are positive when they turn +x toward +y (clockwise on a y-down screen). A segment's face is
 * half-open, [p1, p2), as in the package, so that two faces meeting at a corner never both report it; corners
 * belong to zero-radius circles. "Closing" is always judged from the current positions: a ball that touches
 * or overlaps an obstacle and moves toward it collides at time 0, one that moves away never collides with it.
 * Every rotating method at angular velocity exactly 0 answers as its static counterpart.
 * <p>
 * Degenerate input gets an answer, never an exception, where the package gave one (a NaN, often): a zero-length
 * segment has no face, a reflection whose normal is undefined (coinciding centres) leaves the velocity as it is.
 * <p>
 * The static methods are closed forms in numerically stable forms. The rotating methods search the foresight
 * window {@code [0, maximumForesight]} and report only contacts inside it; see {@link RotatingContactSearch}.
 * <p>
 * Over 400 lines because it is the API's one implementation of the whole {@link GeometryInterface}, which the API
 * fixes in one class; the closed forms its methods share are {@link ClosedForms}', the rotating search
 * {@link RotatingContactSearch}'s.
 */
public class GeometryImpl implements GeometryInterface {
    /** Default foresight of the rotating methods, in seconds. */
    static final double DEFAULT_FORESIGHT = 1.0;
    /** Default number of slices over which the rotating search computes its motion bounds. */
    static final int DEFAULT_SEARCH_SLICES = 16;
    /**
     * How far (in L) the foot of the perpendicular may lie beyond an end of a rotating segment and the ball still be
     * reflected off its face by {@link #reflectRotatingWall}: far above the rounding that turning the segment and
     * moving the ball to a contact {@link #timeUntilRotatingWallCollision} reported can put there, far below
     * anything a caller can see. Beyond it the velocity comes back unchanged, as from the package.
     */
    static final double END_ROUNDING = 1e-9;

    private final double maximumForesight;
    private final int searchSlices;

    /** The default geometry: foresight {@link #DEFAULT_FORESIGHT}, {@link #DEFAULT_SEARCH_SLICES} slices. */
    public GeometryImpl() {
        this(DEFAULT_FORESIGHT, DEFAULT_SEARCH_SLICES);
    }

    /**
     * @param maximumForesight the rotating methods report contacts at times in [0, maximumForesight] only; finite, &gt; 0
     * @param searchSlices     the number of slices of the foresight window over which the rotating search bounds
     *                         the motion; &ge; 1. More slices give tighter bounds (fewer steps) for fast balls.
     *                         Any value finds the same contacts.
     */
    public GeometryImpl(double maximumForesight, int searchSlices) {
        if (!(maximumForesight > 0) || Double.isInfinite(maximumForesight)) {
            throw new IllegalArgumentException("maximumForesight must be finite and > 0, got " + maximumForesight);
        }
        if (searchSlices < 1) {
            throw new IllegalArgumentException("searchSlices must be >= 1, got " + searchSlices);
        }
        this.maximumForesight = maximumForesight;
        this.searchSlices = searchSlices;
    }

    /**
     * The real roots of a x&sup2; + b x + c = 0, smaller first (a double root twice; for a = 0 the single root
     * of the linear equation twice), computed without cancellation; {@link Geometry#DOUBLE_PAIR_NAN} if there is
     * no real root, or no particular one (a = b = c = 0: every x is a root).
     */
    @Override
    public DoublePair quadraticSolution(double a, double b, double c) {
        if (a == 0) {
            if (b == 0) {
                return Geometry.DOUBLE_PAIR_NAN;
            }
            return new DoublePair(-c / b);
        }
        double discriminant = b * b - 4 * a * c;
        if (discriminant < 0) {
            return Geometry.DOUBLE_PAIR_NAN;
        }
        // q has the sign of b, so b + sign(b) sqrt(disc) never cancels; the roots are q/a and c/q.
        double q = -0.5 * (b + Math.copySign(Math.sqrt(discriminant), b));
        if (q == 0) {
            return new DoublePair(0);
        }
        double r1 = q / a;
        double r2 = c / q;
        return new DoublePair(Math.min(r1, r2), Math.max(r1, r2));
    }

    /** The smaller real root of a x&sup2; + b x + c = 0 (see {@link #quadraticSolution}); NaN if there is none. */
    @Override
    public double minQuadraticSolution(double a, double b, double c) {
        return quadraticSolution(a, b, c).d1;
    }

    /**
     * The foot of the perpendicular from point to the line's segment, or null if it falls off the closed segment;
     * for a segment of zero length, its one point.
     */
    @Override
    public Vect perpendicularPoint(LineSegment line, Vect point) {
        // On the components, each step the doubles of the Vect arithmetic it stands for (a made vector's + 0.0 too):
        // only the foot is made. dir = p2 - p1.
        Vect p1 = line.p1();
        Vect p2 = line.p2();
        double dirX = p2.x() - p1.x() + 0.0;
        double dirY = p2.y() - p1.y() + 0.0;
        if (dirX == 0 && dirY == 0) {
            return p1;
        }
        // Measured from each end, so that swapping the ends gives exactly the same decision.
        double fromP1 = (point.x() - p1.x() + 0.0) * dirX + (point.y() - p1.y() + 0.0) * dirY;
        double fromP2 = (p2.x() - point.x() + 0.0) * dirX + (p2.y() - point.y() + 0.0) * dirY;
        if (fromP1 < 0 || fromP2 < 0) {
            return null;
        }
        double along = fromP1 / (dirX * dirX + dirY * dirY);
        return new Vect(p1.x() + (dirX * along + 0.0), p1.y() + (dirY * along + 0.0));
    }

    /**
     * The foot of the perpendicular from point to the infinite line through the segment; for a segment of zero
     * length, its one point.
     */
    @Override
    public Vect perpendicularPointWholeLine(LineSegment line, Vect point) {
        Vect dir = line.p2().minus(line.p1());
        if (dir.x() == 0 && dir.y() == 0) {
            return line.p1();
        }
        return line.p1().plus(dir.times(point.minus(line.p1()).dot(dir) / dir.dot(dir)));
    }

    /**
     * Given an incident velocity and its perfect (coefficient 1) reflection, the reflection with the given
     * coefficient: the tangential part is kept and the reflected normal part is multiplied by the coefficient.
     */
    @Override
    public Vect applyReflectionCoeff(Vect incidentVect, Vect reflectedVect, double reflectionCoeff) {
        // reflected - incident is -2 times the incident normal part; add back (1 - coeff) of that normal part.
        return reflectedVect.minus(reflectedVect.minus(incidentVect).times((1 - reflectionCoeff) / 2));
    }

    /**
     * Time until the ball touches the flat face of the segment (either side): the foot of the perpendicular from
     * its centre lies on [p1, p2), p1 included and p2 not, as in the package. Contacts beyond the ends, and at p2,
     * are left to zero-radius circles at the ends. Touching or overlapping and closing gives 0; moving away,
     * parallel or at rest, or a segment of zero length, gives infinity.
     */
    @Override
    public double timeUntilWallCollision(LineSegment line, Circle ball, Vect velocity) {
        // Reckoned on the components by a method of its own, so that this one is small enough for the JIT to inline
        // into its caller, and a circle and a vector the caller makes for the question need not be made at all.
        return timeUntilFace(line, ball.getCenter().x(), ball.getCenter().y(), ball.getRadius(), velocity.x(),
                velocity.y());
    }

    /** The velocity reflected off the segment's line, its normal part multiplied by the coefficient. */
    @Override
    public Vect reflectWall(LineSegment line, Vect velocity, double reflectionCoeff) {
        // The unit normal (-dy, dx) of the direction, as Vect's minus and unitSize make it (-0 turned to +0), without
        // making those vectors: a bounce off a wall is the commonest collision.
        double dx = line.p2().x() - line.p1().x() + 0.0;
        double dy = line.p2().y() - line.p1().y() + 0.0;
        double nx = -dy + 0.0;
        double ny = dx + 0.0;
        double normal = length(nx, ny);
        if (normal == 0) {
            return reflectAlong(Vect.ZERO, velocity, reflectionCoeff);
        }
        return reflectAlong(nx / normal + 0.0, ny / normal + 0.0, velocity, reflectionCoeff);
    }

    /** {@link #reflectWall(LineSegment, Vect, double)} with coefficient 1. */
    @Override
    public Vect reflectWall(LineSegment line, Vect velocity) {
        return reflectWall(line, velocity, 1);
    }

    @Override
    public double distanceSquared(Vect v1, Vect v2) {
        return v1.distanceSquared(v2);
    }

    @Override
    public double distanceSquared(double x1, double y1, double x2, double y2) {
        double dx = x2 - x1;
        double dy = y2 - y1;
        return dx * dx + dy * dy;
    }

    /**
     * Time until the moving ball touches the fixed circle (a zero-radius circle is a corner).
     * Touching or overlapping and closing gives 0; moving away or at rest gives infinity.
     */
    @Override
    public double timeUntilCircleCollision(Circle circle, Circle ball, Vect velocity) {
        Vect c = circle.getCenter();
        Vect b = ball.getCenter();
        return timeUntilCentresAt(b.x() - c.x(), b.y() - c.y(), velocity.x(), velocity.y(),
                circle.getRadius() + ball.getRadius());
    }

    /**
     * The velocity reflected off the circle at the ball's position, normal part times the coefficient; unchanged
     * when the centres coincide (no normal).
     */
    @Override
    public Vect reflectCircle(Vect circleCenter, Vect ballCenter, Vect ballVelocity, double reflectionCoeff) {
        return reflectAlong(ballCenter.minus(circleCenter).unitSize(), ballVelocity, reflectionCoeff);
    }

    /** {@link #reflectCircle(Vect, Vect, Vect, double)} with coefficient 1. */
    @Override
    public Vect reflectCircle(Vect circleCenter, Vect ballCenter, Vect ballVelocity) {
        return reflectCircle(circleCenter, ballCenter, ballVelocity, 1);
    }

    /** The point turned by the angle about the centre of rotation (+x toward +y). */
    @Override
    public Vect rotateAround(Vect point, Vect centerOfRotation, Angle angle) {
        // centre + (point - centre) turned, on the components as Vect's minus, rotateBy and plus reckon them
        double dx = point.x() - centerOfRotation.x() + 0.0;
        double dy = point.y() - centerOfRotation.y() + 0.0;
        double c = angle.cos();
        double s = angle.sin();
        double turnedX = dx * c - dy * s + 0.0;
        double turnedY = dx * s + dy * c + 0.0;
        return new Vect(centerOfRotation.x() + turnedX, centerOfRotation.y() + turnedY);
    }

    @Override
    public LineSegment rotateAround(LineSegment line, Vect centerOfRotation, Angle angle) {
        return new LineSegment(rotateAround(line.p1(), centerOfRotation, angle),
                rotateAround(line.p2(), centerOfRotation, angle));
    }

    @Override
    public Circle rotateAround(Circle circle, Vect centerOfRotation, Angle angle) {
        return new Circle(rotateAround(circle.getCenter(), centerOfRotation, angle), circle.getRadius());
    }

    /**
     * The two times (smaller first, possibly negative) at which a point moving from {@code point} with the
     * velocity lies on the circle; equal when it grazes; {@link Geometry#DOUBLE_PAIR_NAN} if its line of motion
     * misses the circle or the velocity is zero.
     */
    @Override
    public DoublePair timeUntilCircleCollision(Circle circle, Vect point, Vect velocity) {
        double dx = point.x() - circle.getCenter().x();
        double dy = point.y() - circle.getCenter().y();
        double speedSquared = velocity.dot(velocity);
        double discriminant = quarterDiscriminant(dx, dy, velocity.x(), velocity.y(), circle.getRadius());
        if (speedSquared == 0 || discriminant < 0) {
            return Geometry.DOUBLE_PAIR_NAN;
        }
        double along = dx * velocity.x() + dy * velocity.y();
        double q = -(along + Math.copySign(Math.sqrt(discriminant), along));
        if (q == 0) {
            return new DoublePair(0);
        }
        double r1 = q / speedSquared;
        double r2 = excessSquared(dx, dy, circle.getRadius()) / q;
        return new DoublePair(Math.min(r1, r2), Math.max(r1, r2));
    }

    /**
     * Time until the ball touches the face of the segment that turns about {@code center} at
     * {@code angularVelocity} rad/s (positive turns +x toward +y) from its given position at time 0: what
     * {@link #timeUntilWallCollision} means, turning. Contacts whose foot lies on the segment are found; contacts
     * beyond the ends are left to zero-radius circles there ({@link #timeUntilRotatingCircleCollision}). At angular
     * velocity 0 the answer is {@link #timeUntilWallCollision}'s. Otherwise only times in [0, maximumForesight] are
     * reported, so a caller whose rotation stops earlier uses an instance whose foresight is the remaining rotation
     * time and then treats the segment as static at its stop angle. At the returned time the ball is within
     * 1e-10 L of touching the face; touching or overlapping the face and closing is 0. A contact that begins
     * touching at zero closing speed and is then closed on is reported as soon as it closes at a speed a
     * reflection can act on. A ball at rest is found. No contact is missed or found late, which the package's
     * sampled search does on about one rotating contact in ten. Infinity for a segment of zero length or an angular
     * velocity, ball or velocity that is not finite. See {@link RotatingContactSearch}.
     */
    @Override
    public double timeUntilRotatingWallCollision(LineSegment line, Vect center, double angularVelocity, Circle ball,
                                                 Vect velocity) {
        if (angularVelocity == 0) {
            return timeUntilWallCollision(line, ball, velocity);
        }
        if (line.p1().equals(line.p2()) || !searchable(center, angularVelocity, ball, velocity)) {
            return Double.POSITIVE_INFINITY;
        }
        return RotatingContactSearch.firstFaceContact(line, center, angularVelocity, ball, velocity, maximumForesight,
                searchSlices);
    }

    /** Whether the rotating search has a motion to follow: every number it starts from is finite. */
    private static boolean searchable(Vect center, double angularVelocity, Circle ball, Vect velocity) {
        Vect c = ball.getCenter();
        return Double.isFinite(angularVelocity) && Double.isFinite(ball.getRadius())
                && Double.isFinite(center.x() + center.y() + c.x() + c.y() + velocity.x() + velocity.y());
    }

    /** {@link #reflectRotatingWall(LineSegment, Vect, double, Circle, Vect, double)} with coefficient 1. */
    @Override
    public Vect reflectRotatingWall(LineSegment line, Vect center, double angularVelocity, Circle ball,
                                    Vect velocity) {
        return reflectRotatingWall(line, center, angularVelocity, ball, velocity, 1);
    }

    /**
     * The ball's velocity after it bounces off the face of the segment that turns about {@code center} at
     * {@code angularVelocity}, as the package answers it, wherever the ball is (callers often reflect before they
     * move the ball to the contact): at the foot of the perpendicular from the ball's centre, the velocity relative
     * to the segment's surface there, w &times; (foot - center), is reflected off the segment's line with the
     * coefficient, and the surface velocity is added back. When that foot lies beyond an end (by more than
     * {@link #END_ROUNDING}), the velocity comes back unchanged: that is the end's contact, which belongs to
     * {@link #reflectRotatingCircle} with a zero-radius circle there. At angular velocity 0 it is
     * {@link #reflectWall(LineSegment, Vect, double)}; a segment of zero length leaves the velocity unchanged.
     */
    @Override
    public Vect reflectRotatingWall(LineSegment line, Vect center, double angularVelocity, Circle ball, Vect velocity,
                                    double reflectionCoeff) {
        if (angularVelocity == 0) {
            return reflectWall(line, velocity, reflectionCoeff);
        }
        double length = line.length();
        if (length == 0) {
            return velocity;
        }
        Vect unitAlong = line.p2().minus(line.p1()).times(1 / length);
        double along = ball.getCenter().minus(line.p1()).dot(unitAlong);
        if (along < -END_ROUNDING || along > length + END_ROUNDING) {
            return velocity;
        }
        Vect foot = line.p1().plus(unitAlong.times(along));
        Vect unitNormal = new Vect(-unitAlong.y(), unitAlong.x());
        return reflectOffMovingSurface(unitNormal, foot, center, angularVelocity, velocity, reflectionCoeff);
    }

    /**
     * Time until the ball touches the circle whose centre turns about {@code center} at {@code angularVelocity}
     * rad/s; the same contract as {@link #timeUntilRotatingWallCollision}, and at angular velocity 0
     * {@link #timeUntilCircleCollision(Circle, Circle, Vect)}'s answer.
     */
    @Override
    public double timeUntilRotatingCircleCollision(Circle circle, Vect center, double angularVelocity, Circle ball,
                                                   Vect velocity) {
        if (angularVelocity == 0) {
            return timeUntilCircleCollision(circle, ball, velocity);
        }
        if (!searchable(center, angularVelocity, ball, velocity) || !Double.isFinite(circle.getRadius())
                || !Double.isFinite(circle.getCenter().x() + circle.getCenter().y())) {
            return Double.POSITIVE_INFINITY;
        }
        return RotatingContactSearch.firstCircleContact(circle, center, angularVelocity, ball, velocity,
                maximumForesight, searchSlices);
    }

    /** {@link #reflectRotatingCircle(Circle, Vect, double, Circle, Vect, double)} with coefficient 1. */
    @Override
    public Vect reflectRotatingCircle(Circle circle, Vect center, double angularVelocity, Circle ball,
                                      Vect velocity) {
        return reflectRotatingCircle(circle, center, angularVelocity, ball, velocity, 1);
    }

    /**
     * The ball's velocity after it bounces off the circle (in its current position) whose centre turns about
     * {@code center} at {@code angularVelocity}: the velocity relative to the circle's surface at the contact
     * point is reflected along the line of centres with the coefficient, and the surface velocity added back. At
     * angular velocity 0 it is {@link #reflectCircle(Vect, Vect, Vect, double)}; coinciding centres leave the
     * velocity unchanged.
     */
    @Override
    public Vect reflectRotatingCircle(Circle circle, Vect center, double angularVelocity, Circle ball, Vect velocity,
                                      double reflectionCoeff) {
        if (angularVelocity == 0) {
            return reflectCircle(circle.getCenter(), ball.getCenter(), velocity, reflectionCoeff);
        }
        Vect normal = ball.getCenter().minus(circle.getCenter()).unitSize();
        if (normal.equals(Vect.ZERO)) {
            return velocity;
        }
        Vect contact = circle.getCenter().plus(normal.times(circle.getRadius()));
        return reflectOffMovingSurface(normal, contact, center, angularVelocity, velocity, reflectionCoeff);
    }

    /**
     * Time until two moving balls touch. Touching or overlapping and closing gives 0; separating or equal
     * velocities give infinity.
     */
    @Override
    public double timeUntilBallBallCollision(Circle ball1, Vect velocity1, Circle ball2, Vect velocity2) {
        Vect c1 = ball1.getCenter();
        Vect c2 = ball2.getCenter();
        return timeUntilCentresAt(c1.x() - c2.x(), c1.y() - c2.y(), velocity1.x() - velocity2.x(),
                velocity1.y() - velocity2.y(), ball1.getRadius() + ball2.getRadius());
    }

    /**
     * The velocities after a perfectly elastic collision of two balls touching at their current centres: the
     * normal parts are exchanged as momentum and energy conservation require, the tangential parts kept.
     * One mass may be {@code Double.POSITIVE_INFINITY} (an immovable ball). Where there is no answer (coinciding
     * centres, so no normal; masses whose ratio is undefined, both zero or both infinite) the velocities are
     * unchanged.
     */
    @Override
    public VectPair reflectBalls(Vect center1, double mass1, Vect velocity1, Vect center2, double mass2,
                                 Vect velocity2) {
        // Along d = centre 2 - centre 1 the normal part of u = v1 - v2 is d (u.d) / (d.d): no square root and no
        // allocation but the result. d may be scaled freely, which keeps d.d normal for any distance.
        double dx = center2.x() - center1.x();
        double dy = center2.y() - center1.y();
        double dd = dx * dx + dy * dy;
        if (dd < Double.MIN_NORMAL || dd == Double.POSITIVE_INFINITY) {
            double scale = Math.max(Math.abs(dx), Math.abs(dy));
            dx /= scale;
            dy /= scale;
            dd = dx * dx + dy * dy;
        }
        double approach = ((velocity1.x() - velocity2.x()) * dx + (velocity1.y() - velocity2.y()) * dy) / dd;
        // 2 m2 / (m1 + m2) and 2 m1 / (m1 + m2), written with mass ratios so that an infinite mass works.
        double change1 = 2 / (1 + mass1 / mass2) * approach;
        double change2 = 2 / (1 + mass2 / mass1) * approach;
        if (Double.isNaN(change1) || Double.isNaN(change2)) {
            return new VectPair(velocity1, velocity2);
        }
        return new VectPair(new Vect(velocity1.x() - dx * change1, velocity1.y() - dy * change1),
                new Vect(velocity2.x() + dx * change2, velocity2.y() + dy * change2));
    }
}
