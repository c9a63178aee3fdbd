package physics;

import java.awt.geom.Ellipse2D;
import java.awt.geom.Point2D;
import java.io.Serializable;

/**
 * An immutable circle: a centre and a radius (radius 0 is a point, used for corners). Any radius is accepted, as in
 * the package; the collision methods answer for a negative or NaN one from their formulas.
 */
public final class Circle implements Serializable {
    private static final long serialVersionUID = 1L;

    private final Vect center;
    private final double radius;

    public Circle(Vect center, double radius) {
        this.center = center;
        this.radius = radius + 0.0;
    }

    public Circle(double cx, double cy, double radius) {
        this(new Vect(cx, cy), radius);
    }

    public Circle(Point2D center, double radius) {
        this(new Vect(center), radius);
    }

    public Vect getCenter() {
        return center;
    }

    public double getRadius() {
        return radius;
    }

    public Ellipse2D toEllipse2D() {
        return new Ellipse2D.Double(center.x() - radius, center.y() - radius, 2 * radius, 2 * radius);
    }

    public boolean equals(Circle other) {
        return other != null && center.equals(other.center) && Double.compare(radius, other.radius) == 0;
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof Circle c && equals(c);
    }

    @Override
    public int hashCode() {
        return 31 * center.hashCode() + Double.hashCode(radius);
    }

    @Override
    public String toString() {
        return "[Circle center=" + center + " radius=" + radius + "]";
    }
}
