package physics;

import java.awt.geom.Point2D;
import java.io.Serializable;

/**
 * An immutable 2-D vector held only in Cartesian form (no cached polar form, so every result depends only on
 * x and y). Any components are accepted, NaN too, as in the package. Equality is exact, with 0.0 and -0.0 equal
 * and NaN equal to NaN, so that it agrees with {@code hashCode} and a vector always equals itself.
 */
public final class Vect implements Serializable {
    private static final long serialVersionUID = 1L;

    public static final Vect ZERO = new Vect(0, 0);
    public static final Vect X_HAT = new Vect(1, 0);
    public static final Vect Y_HAT = new Vect(0, 1);

    private final double x;
    private final double y;

    public Vect(double x, double y) {
        // + 0.0 turns -0.0 into 0.0 so that equal vectors have one representation and one hash code.
        this.x = x + 0.0;
        this.y = y + 0.0;
    }

    /** The unit vector at the given angle. */
    public Vect(Angle angle) {
        this(angle, 1);
    }

    /** The vector of the given length at the given angle. */
    public Vect(Angle angle, double length) {
        this(angle.cos() * length, angle.sin() * length);
    }

    public Vect(Point2D point) {
        this(point.getX(), point.getY());
    }

    public double x() {
        return x;
    }

    public double y() {
        return y;
    }

    /**
     * The direction from +x.
     *
     * @throws IllegalArgumentException for the zero vector, which has none (as in the package)
     */
    public Angle angle() {
        return new Angle(x, y);
    }

    public double length() {
        // Along an axis hypot gives exactly the other component's magnitude (infinity too), without its
        // cost: most walls, faces and bounced velocities lie along an axis.
        if (x == 0) {
            return Math.abs(y);
        }
        if (y == 0) {
            return Math.abs(x);
        }
        return StrictMath.hypot(x, y);
    }

    public double distanceSquared(Vect other) {
        double dx = x - other.x;
        double dy = y - other.y;
        return dx * dx + dy * dy;
    }

    public Vect plus(Vect other) {
        return new Vect(x + other.x, y + other.y);
    }

    public Vect minus(Vect other) {
        return new Vect(x - other.x, y - other.y);
    }

    public Vect neg() {
        return new Vect(-x, -y);
    }

    public Vect times(double factor) {
        return new Vect(x * factor, y * factor);
    }

    public double dot(Vect other) {
        return x * other.x + y * other.y;
    }

    /** This vector turned by the angle about the origin (+x toward +y). */
    public Vect rotateBy(Angle angle) {
        double c = angle.cos();
        double s = angle.sin();
        return new Vect(x * c - y * s, x * s + y * c);
    }

    /** The projection of this vector on the direction of {@code onto}; projecting on the zero vector gives ZERO. */
    public Vect projectOn(Vect onto) {
        double lengthSquared = onto.dot(onto);
        if (lengthSquared == 0) {
            return ZERO;
        }
        return onto.times(dot(onto) / lengthSquared);
    }

    /** The unit vector in this direction; the zero vector gives ZERO (a defined answer, not NaN). */
    public Vect unitSize() {
        double length = length();
        if (length == 0) {
            return ZERO;
        }
        return new Vect(x / length, y / length);
    }

    public Point2D.Double toPoint2D() {
        return new Point2D.Double(x, y);
    }

    public boolean equals(Vect other) {
        return other != null && Double.compare(x, other.x) == 0 && Double.compare(y, other.y) == 0;
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof Vect v && equals(v);
    }

    @Override
    public int hashCode() {
        return 31 * Double.hashCode(x) + Double.hashCode(y);
    }

    @Override
    public String toString() {
        return "<" + x + "," + y + ">";
    }
}
