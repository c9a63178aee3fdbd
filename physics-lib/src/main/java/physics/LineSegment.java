package physics;

import java.awt.geom.Line2D;
import java.io.Serializable;

/**
 * An immutable line segment from p1 to p2. Equality compares the ordered end points. Its face, for the wall
 * methods, is half-open, [p1, p2), as in the package. A segment of zero length is accepted, as in the package: it
 * has no face (no wall collision, no reflection) and no {@link #angle()}.
 */
public final class LineSegment implements Serializable {
    private static final long serialVersionUID = 1L;

    private final Vect p1;
    private final Vect p2;

    public LineSegment(Vect p1, Vect p2) {
        this.p1 = p1;
        this.p2 = p2;
    }

    public LineSegment(Line2D line) {
        this(new Vect(line.getP1()), new Vect(line.getP2()));
    }

    public LineSegment(double x1, double y1, double x2, double y2) {
        this(new Vect(x1, y1), new Vect(x2, y2));
    }

    public Vect p1() {
        return p1;
    }

    public Vect p2() {
        return p2;
    }

    public Line2D.Double toLine2D() {
        return new Line2D.Double(p1.x(), p1.y(), p2.x(), p2.y());
    }

    /**
     * The direction of p2 - p1.
     *
     * @throws IllegalArgumentException for a segment of zero length, which has none (as in the package)
     */
    public Angle angle() {
        return p2.minus(p1).angle();
    }

    public double length() {
        return p2.minus(p1).length();
    }

    public boolean equals(LineSegment other) {
        return other != null && p1.equals(other.p1) && p2.equals(other.p2);
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof LineSegment s && equals(s);
    }

    @Override
    public int hashCode() {
        return 31 * p1.hashCode() + p2.hashCode();
    }

    @Override
    public String toString() {
        return "LineSegment(" + p1 + "-" + p2 + ")";
    }
}
