package physics;

/**
 * The closed forms that {@link GeometryImpl}'s methods share, in numerically stable forms and on components where an
 * engine asks them often, so that they make no vector: lengths and norms, the half-open face test, the time until two
 * centres are a distance apart, and reflection along a normal, off a still or a turning surface.
 */
final class ClosedForms {
    private ClosedForms() {
    }

    /** {@link Vect#length()} of (x, y), made of no vector. */
    static double length(double x, double y) {
        if (x == 0) {
            return Math.abs(y);
        }
        if (y == 0) {
            return Math.abs(x);
        }
        return StrictMath.hypot(x, y);
    }

    /** Whether the foot of the perpendicular from the point (px, py) lies on the half-open face [p1, p2). */
    static boolean footOnFace(LineSegment line, double px, double py) {
        Vect p1 = line.p1();
        Vect p2 = line.p2();
        double dirX = p2.x() - p1.x() + 0.0;
        double dirY = p2.y() - p1.y() + 0.0;
        return (px - p1.x() + 0.0) * dirX + (py - p1.y() + 0.0) * dirY >= 0
                && (p2.x() - px + 0.0) * dirX + (p2.y() - py + 0.0) * dirY > 0;
    }

    /** Reflects the velocity relative to the surface point turning with the obstacle, then adds its velocity back. */
    static Vect reflectOffMovingSurface(Vect unitNormal, Vect contact, Vect pivot, double angularVelocity,
                                                Vect velocity, double reflectionCoeff) {
        Vect arm = contact.minus(pivot);
        Vect surfaceVelocity = new Vect(-arm.y(), arm.x()).times(angularVelocity);
        return reflectAlong(unitNormal, velocity.minus(surfaceVelocity), reflectionCoeff).plus(surfaceVelocity);
    }

    /**
     * Time until |d + u t| first equals distance, for the closest-approach problems (circle-ball, ball-ball), on
     * the components of the offset d and the velocity u so that nothing is allocated. Uses (|d| - S)(|d| + S) for
     * |d|&sup2; - S&sup2; and Lagrange's identity for the discriminant, and picks the root form without
     * cancellation, so far-away contacts keep their digits.
     */
    static double timeUntilCentresAt(double dx, double dy, double ux, double uy, double distance) {
        double along = dx * ux + dy * uy;
        if (!(along < 0)) {
            return Double.POSITIVE_INFINITY; // not closing: never, whether apart, touching or overlapping
        }
        double excess = excessSquared(dx, dy, distance);
        if (excess <= 0) {
            return 0;
        }
        double discriminant = quarterDiscriminant(dx, dy, ux, uy, distance);
        if (discriminant < 0) {
            return Double.POSITIVE_INFINITY;
        }
        return excess / (-along + Math.sqrt(discriminant));
    }

    /**
     * {@link GeometryImpl#timeUntilWallCollision}, for a ball of {@code radius} centred at (centerX, centerY) moving at
     * (velocityX, velocityY).
     */
    static double timeUntilFace(LineSegment line, double centerX, double centerY, double radius, double velocityX,
                                double velocityY) {
        // On the components, making no vector (an engine asks this for every face in reach of every ball): each
        // step is the Vect arithmetic it stands for, in the same order, so the doubles are the same. A component
        // of a vector made from a sum or product gets + 0.0, as Vect's constructor adds (no -0.0 in a Vect).
        Vect p1 = line.p1();
        Vect p2 = line.p2();
        double dirX = p2.x() - p1.x() + 0.0;
        double dirY = p2.y() - p1.y() + 0.0;
        // normal = new Vect(-dir.y, dir.x).unitSize()
        double perpX = -dirY + 0.0;
        double perpY = dirX + 0.0;
        double perpLength = length(perpX, perpY);
        double normalX = perpLength == 0 ? 0 : perpX / perpLength + 0.0;
        double normalY = perpLength == 0 ? 0 : perpY / perpLength + 0.0;
        double offset = (centerX - p1.x() + 0.0) * normalX + (centerY - p1.y() + 0.0) * normalY;
        double normalSpeed = velocityX * normalX + velocityY * normalY;
        // Rate of change of |offset|; a centre exactly on the line moves away from it whichever way it goes.
        double closingRate = offset == 0 ? Math.abs(normalSpeed) : Math.signum(offset) * normalSpeed;
        double gap = Math.abs(offset) - radius;
        if (gap <= 0) {
            return closingRate < 0 && footOnFace(line, centerX, centerY) ? 0 : Double.POSITIVE_INFINITY;
        }
        if (closingRate >= 0) {
            return Double.POSITIVE_INFINITY;
        }
        double time = gap / -closingRate;
        if (time == Double.POSITIVE_INFINITY) {
            // A subnormal closing speed: the contact lies beyond the range of doubles, and moving the centre
            // by an infinite time would turn its zero components into NaN.
            return time;
        }
        // the centre at contact: center.plus(velocity.times(time))
        double atX = centerX + (velocityX * time + 0.0) + 0.0;
        double atY = centerY + (velocityY * time + 0.0) + 0.0;
        return footOnFace(line, atX, atY) ? time : Double.POSITIVE_INFINITY;
    }

    /** |d|&sup2; - radius&sup2;, as a product of sum and difference. */
    static double excessSquared(double dx, double dy, double radius) {
        double length = norm(dx, dy);
        return (length - radius) * (length + radius);
    }

    /** (d.u)&sup2; - |u|&sup2;(|d|&sup2; - r&sup2;) = |u|&sup2;r&sup2; - (d x u)&sup2;, factored. */
    static double quarterDiscriminant(double dx, double dy, double ux, double uy, double radius) {
        double cross = Math.abs(dx * uy - dy * ux);
        double reach = norm(ux, uy) * radius;
        return (reach - cross) * (reach + cross);
    }

    /**
     * |(x, y)|: the square root of the sum of squares, within an ulp like {@link Math#hypot} at a fraction of its
     * cost; hypot only where the squares would underflow or overflow.
     */
    static double norm(double x, double y) {
        double sumOfSquares = x * x + y * y;
        if (sumOfSquares < Double.MIN_NORMAL || sumOfSquares == Double.POSITIVE_INFINITY) {
            return StrictMath.hypot(x, y);
        }
        return Math.sqrt(sumOfSquares);
    }

    /** v with its part along the unit normal replaced by -coeff times that part. */
    static Vect reflectAlong(Vect unitNormal, Vect velocity, double reflectionCoeff) {
        return reflectAlong(unitNormal.x(), unitNormal.y(), velocity, reflectionCoeff);
    }

    /** {@link #reflectAlong(Vect, Vect, double)} about the unit normal (nx, ny), making only the result. */
    static Vect reflectAlong(double nx, double ny, Vect velocity, double reflectionCoeff) {
        double along = (1 + reflectionCoeff) * (velocity.x() * nx + velocity.y() * ny);
        // velocity.minus(unitNormal.times(along)), each made vector's -0 turned to +0 as Vect does
        return new Vect(velocity.x() - (nx * along + 0.0), velocity.y() - (ny * along + 0.0));
    }
}
