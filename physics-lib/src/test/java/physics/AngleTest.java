package physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

class AngleTest {
    @Test
    void normalisesIntoZeroToTwoPi() {
        assertThat(new Angle(-Math.PI / 2).radians()).isCloseTo(3 * Math.PI / 2, within(1e-15));
        assertThat(new Angle(5 * Math.PI).radians()).isCloseTo(Math.PI, within(1e-14));
        assertThat(new Angle(2 * Math.PI)).isEqualTo(Angle.ZERO);
        assertThat(new Angle(-1e-300).radians()).isLessThan(2 * Math.PI).isGreaterThanOrEqualTo(0);
        assertThat(new Angle(-0.0)).isEqualTo(Angle.ZERO);
    }

    @Test
    void constantsAreTheirDegrees() {
        assertThat(Angle.DEG_45.radians()).isEqualTo(Math.PI / 4);
        assertThat(Angle.DEG_135.radians()).isEqualTo(3 * Math.PI / 4);
        assertThat(Angle.DEG_225.radians()).isEqualTo(5 * Math.PI / 4);
        assertThat(Angle.DEG_270.radians()).isEqualTo(3 * Math.PI / 2);
        assertThat(Angle.DEG_315.radians()).isEqualTo(7 * Math.PI / 4);
        assertThat(Angle.RAD_PI_OVER_FOUR).isEqualTo(Angle.DEG_45);
        assertThat(Angle.RAD_PI_OVER_TWO).isEqualTo(Angle.DEG_90);
        assertThat(Angle.RAD_PI).isEqualTo(Angle.DEG_180);
    }

    @Test
    void fromComponents() {
        assertThat(new Angle(-1, 0)).isEqualTo(Angle.DEG_180);
        assertThat(new Angle(1, 1).radians()).isCloseTo(Math.PI / 4, within(1e-15));
        assertThat(new Angle(0, 0)).isEqualTo(Angle.ZERO);
    }

    @Test
    void trigonometry() {
        Angle a = new Angle(Math.PI / 3);
        assertThat(a.cos()).isCloseTo(0.5, within(1e-15));
        assertThat(a.sin()).isCloseTo(Math.sqrt(3) / 2, within(1e-15));
        assertThat(a.tan()).isCloseTo(Math.sqrt(3), within(1e-14));
    }

    @Test
    void plusAndMinusWrapAround() {
        assertThat(Angle.DEG_270.plus(Angle.DEG_180).radians()).isCloseTo(Math.PI / 2, within(1e-15));
        assertThat(Angle.DEG_45.minus(Angle.DEG_90).radians()).isCloseTo(7 * Math.PI / 4, within(1e-15));
    }

    @Test
    void compareToOrdersByNormalisedRadiansAndEqualsIsConsistent() {
        assertThat(Angle.DEG_45.compareTo(Angle.DEG_90)).isNegative();
        assertThat(java.util.stream.Stream.of(Angle.DEG_90, Angle.DEG_45).sorted().toList()).containsExactly(Angle.DEG_45, Angle.DEG_90);
        assertThat(new Angle(-Math.PI).compareTo(Angle.DEG_180)).isZero();
        assertThat(new Angle(-Math.PI)).isEqualTo(Angle.DEG_180).hasSameHashCodeAs(Angle.DEG_180);
        assertThat(Angle.DEG_45.equals((Angle) null)).isFalse();
    }

    @Test
    void epsilonOnlyWidensCompareToAndIsRestored() {
        Angle a = new Angle(1);
        Angle b = new Angle(1 + 1e-10);
        try {
            Angle.setEpsilon(1e-9);
            assertThat(a.compareTo(b)).isZero();
            assertThat(a).isNotEqualTo(b);
        } finally {
            Angle.setEpsilon(0);
        }
        assertThat(a.compareTo(b)).isNegative();
    }

    @Test
    void badInputIsRejected() {
        assertThatThrownBy(() -> new Angle(Double.NaN)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new Angle(Double.POSITIVE_INFINITY)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> Angle.setEpsilon(-1)).isInstanceOf(IllegalArgumentException.class);
    }
}
