package physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.awt.geom.Point2D;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class VectTest {
    private static final double EPS = 1e-15;

    @Test
    void constantsAndAccessors() {
        assertThat(Vect.ZERO.x()).isZero();
        assertThat(Vect.X_HAT).isEqualTo(new Vect(1, 0));
        assertThat(Vect.Y_HAT).isEqualTo(new Vect(0, 1));
        assertThat(new Vect(3, 4).length()).isEqualTo(5);
    }

    /** Along an axis the length is the other component's magnitude, bit for bit what hypot gives (infinities too). */
    @ParameterizedTest
    @ValueSource(doubles = {0.0, -0.0, 1e-310, -2.5, 3.75e300, Double.MAX_VALUE, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY})
    void lengthAlongAnAxisIsExactlyWhatHypotGives(double component) {
        assertThat(new Vect(component, 0).length()).isEqualTo(Math.hypot(component, 0));
        assertThat(new Vect(0, component).length()).isEqualTo(Math.hypot(0, component));
        assertThat(new Vect(-0.0, component).length()).isEqualTo(Math.hypot(-0.0, component));
        assertThat(Double.doubleToRawLongBits(new Vect(component, 0).length()))
                .isEqualTo(Double.doubleToRawLongBits(Math.hypot(component, 0)));
    }

    @Test
    void polarConstructorsGiveCartesianComponents() {
        Vect v = new Vect(Angle.DEG_90, 2);
        assertThat(v.x()).isCloseTo(0, within(EPS));
        assertThat(v.y()).isCloseTo(2, within(EPS));
        Vect unit = new Vect(new Angle(Math.PI / 3));
        assertThat(unit.x()).isCloseTo(0.5, within(EPS));
        assertThat(unit.y()).isCloseTo(Math.sqrt(3) / 2, within(EPS));
        assertThat(new Vect(new Point2D.Double(1.5, -2))).isEqualTo(new Vect(1.5, -2));
    }

    @Test
    void arithmetic() {
        Vect a = new Vect(1, 2);
        Vect b = new Vect(-3, 5);
        assertThat(a.plus(b)).isEqualTo(new Vect(-2, 7));
        assertThat(a.minus(b)).isEqualTo(new Vect(4, -3));
        assertThat(a.neg()).isEqualTo(new Vect(-1, -2));
        assertThat(a.times(3)).isEqualTo(new Vect(3, 6));
        assertThat(a.dot(b)).isEqualTo(7);
        assertThat(a.distanceSquared(b)).isEqualTo(25);
    }

    @Test
    void rotateByTurnsXTowardY() {
        Vect r = Vect.X_HAT.rotateBy(Angle.DEG_90);
        assertThat(r.x()).isCloseTo(0, within(EPS));
        assertThat(r.y()).isCloseTo(1, within(EPS));
        Vect back = new Vect(2, 1).rotateBy(Angle.DEG_45).rotateBy(Angle.DEG_315);
        assertThat(back.x()).isCloseTo(2, within(1e-15));
        assertThat(back.y()).isCloseTo(1, within(1e-15));
    }

    @Test
    void projectionAndUnitSize() {
        assertThat(new Vect(3, 4).projectOn(new Vect(2, 0))).isEqualTo(new Vect(3, 0));
        assertThat(new Vect(3, 4).unitSize()).isEqualTo(new Vect(0.6, 0.8));
        assertThat(new Vect(3, 4).projectOn(Vect.ZERO)).isEqualTo(Vect.ZERO);
        assertThat(Vect.ZERO.unitSize()).isEqualTo(Vect.ZERO);
    }

    @Test
    void angleOfVector() {
        assertThat(new Vect(0, -1).angle().radians()).isEqualTo(-Math.PI / 2);
        assertThatThrownBy(Vect.ZERO::angle).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void equalityIsExactAndConsistentWithHashCode() {
        assertThat(new Vect(-0.0, 0.0)).isEqualTo(new Vect(0.0, -0.0));
        assertThat(new Vect(-0.0, 0.0).hashCode()).isEqualTo(new Vect(0.0, -0.0).hashCode());
        assertThat(new Vect(1, 2)).isNotEqualTo(new Vect(1, 2.0000000001));
        assertThat(new Vect(1, 2).equals((Vect) null)).isFalse();
        assertThat(new Vect(1, 2).equals((Object) "<1.0,2.0>")).isFalse();
    }

    @Test
    void conversionsAndText() {
        assertThat(new Vect(1, 2).toPoint2D()).isEqualTo(new Point2D.Double(1, 2));
        assertThat(new Vect(1, 2)).hasToString("<1.0,2.0>");
    }

    @Test
    void nanComponentIsAcceptedAndEqualsItself() {
        Vect nan = new Vect(Double.NaN, 0);
        assertThat(nan.x()).isNaN();
        assertThat(nan).hasToString("<NaN,0.0>").isEqualTo(new Vect(Double.NaN, 0))
                .hasSameHashCodeAs(new Vect(Double.NaN, 0));
    }
}
