package physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Point2D;
import org.junit.jupiter.api.Test;

/** Circle and LineSegment: construction, accessors, java.awt.geom conversions, equality. */
class ShapeTest {
    @Test
    void circleConstructorsAgree() {
        Circle c = new Circle(new Vect(1, 2), 3);
        assertThat(new Circle(1, 2, 3)).isEqualTo(c).hasSameHashCodeAs(c);
        assertThat(new Circle(new Point2D.Double(1, 2), 3)).isEqualTo(c);
        assertThat(c.getCenter()).isEqualTo(new Vect(1, 2));
        assertThat(c.getRadius()).isEqualTo(3);
        assertThat(c).isNotEqualTo(new Circle(1, 2, 3.5));
    }

    @Test
    void circleToEllipseIsItsBoundingBox() {
        assertThat(new Circle(1, 2, 3).toEllipse2D()).isEqualTo(new Ellipse2D.Double(-2, -1, 6, 6));
    }

    @Test
    void circleAcceptsAnyRadiusAsThePackageDoes() {
        assertThat(new Circle(0, 0, -1).getRadius()).isEqualTo(-1);
        assertThat(new Circle(0, 0, Double.NaN)).isEqualTo(new Circle(0, 0, Double.NaN));
        assertThat(new Circle(0, 0, 0).getRadius()).isZero();
    }

    @Test
    void segmentConstructorsAgree() {
        LineSegment s = new LineSegment(new Vect(0, 0), new Vect(3, 4));
        assertThat(new LineSegment(0, 0, 3, 4)).isEqualTo(s).hasSameHashCodeAs(s);
        assertThat(new LineSegment(new Line2D.Double(0, 0, 3, 4))).isEqualTo(s);
        assertThat(s.length()).isEqualTo(5);
        assertThat(s.angle().radians()).isCloseTo(Math.atan2(4, 3), within(1e-15));
        assertThat(s.p1()).isEqualTo(Vect.ZERO);
        assertThat(s.p2()).isEqualTo(new Vect(3, 4));
    }

    @Test
    void segmentToLine2D() {
        Line2D.Double line = new LineSegment(1, 2, 3, 4).toLine2D();
        assertThat(line.getP1()).isEqualTo(new Point2D.Double(1, 2));
        assertThat(line.getP2()).isEqualTo(new Point2D.Double(3, 4));
    }

    @Test
    void segmentEqualityIsOrdered() {
        assertThat(new LineSegment(0, 0, 1, 0)).isNotEqualTo(new LineSegment(1, 0, 0, 0));
    }

    @Test
    void segmentTextAndCircleTextNameTheirParts() {
        assertThat(new LineSegment(0, 0, 1, 0).toString()).contains("<0.0,0.0>", "<1.0,0.0>");
        assertThat(new Circle(0, 0, 2).toString()).contains("2.0");
    }
}
