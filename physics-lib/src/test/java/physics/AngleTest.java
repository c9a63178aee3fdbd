package physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

class AngleTest {
    @Test
    void radiansAreInMinusPiToPi() {
        assertThat(new Angle(-Math.PI / 2).radians()).isEqualTo(-Math.PI / 2);
        assertThat(new Angle(5 * Math.PI).radians()).isEqualTo(Math.PI);
        assertThat(new Angle(-Math.PI).radians()).as("-pi is the direction pi").isEqualTo(Math.PI);
        assertThat(new Angle(2 * Math.PI)).isEqualTo(Angle.ZERO);
        assertThat(new Angle(-1e-300).radians()).isEqualTo(-1e-300);
        assertThat(new Angle(-0.0)).isEqualTo(Angle.ZERO);
    }

    @Test
    void constantsAreTheirDegrees() {
        assertThat(Angle.DEG_45.radians()).isEqualTo(Math.PI / 4);
        assertThat(Angle.DEG_135.radians()).isEqualTo(3 * Math.PI / 4);
        assertThat(Angle.DEG_225.radians()).isEqualTo(-3 * Math.PI / 4);
        assertThat(Angle.DEG_270.radians()).isEqualTo(-Math.PI / 2);
        assertThat(Angle.DEG_315.radians()).isEqualTo(-Math.PI / 4);
        assertThat(Angle.RAD_PI_OVER_FOUR).isSameAs(Angle.DEG_45);
        assertThat(Angle.RAD_PI_OVER_TWO).isSameAs(Angle.DEG_90);
        assertThat(Angle.RAD_PI).isSameAs(Angle.DEG_180);
    }

    @Test
    void fromComponents() {
        assertThat(new Angle(-1, 0)).isEqualTo(Angle.DEG_180);
        assertThat(new Angle(-3, 0).cos()).isEqualTo(-1.0);
        assertThat(new Angle(1, 1).radians()).isCloseTo(Math.PI / 4, within(1e-15));
        assertThat(new Angle(3, 4).cos()).isEqualTo(0.6);
        assertThatThrownBy(() -> new Angle(0, 0)).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void trigonometry() {
        Angle a = new Angle(Math.PI / 3);
        assertThat(a.cos()).isCloseTo(0.5, within(1e-15));
        assertThat(a.sin()).isCloseTo(Math.sqrt(3) / 2, within(1e-15));
        assertThat(a.tan()).isCloseTo(Math.sqrt(3), within(1e-14));
    }

    @Test
    void plusAndMinusWrapAroundAndKeepQuarterTurnsExact() {
        assertThat(Angle.DEG_270.plus(Angle.DEG_180).radians()).isEqualTo(Math.PI / 2);
        assertThat(Angle.DEG_270.plus(Angle.DEG_180).cos()).isEqualTo(0.0);
        assertThat(Angle.DEG_45.minus(Angle.DEG_90).radians()).isCloseTo(-Math.PI / 4, within(1e-15));
        assertThat(Angle.DEG_45.plus(Angle.DEG_45).sin()).isEqualTo(1.0);
        assertThat(Angle.DEG_90.minus(Angle.DEG_270).cos()).isEqualTo(-1.0);
    }

    @Test
    void compareToAgreesWithEqualsAndOrdersByRadians() {
        assertThat(Angle.DEG_45.compareTo(Angle.DEG_90)).isNegative();
        assertThat(java.util.stream.Stream.of(Angle.DEG_90, Angle.DEG_45).sorted().toList())
                .containsExactly(Angle.DEG_45, Angle.DEG_90);
        assertThat(new Angle(-Math.PI).compareTo(Angle.DEG_180)).isZero();
        assertThat(new Angle(-Math.PI)).isEqualTo(Angle.DEG_180).hasSameHashCodeAs(Angle.DEG_180);
        assertThat(new Angle(0.3)).isEqualTo(new Angle(0.3 + 2 * Math.PI)).hasSameHashCodeAs(new Angle(1.2));
        assertThat(Angle.DEG_45.equals((Angle) null)).isFalse();
    }

    @Test
    void epsilonIsTheToleranceOfEqualsAndCompareToAndIsRestored() {
        Angle a = new Angle(1);
        Angle b = new Angle(1 + 1e-7);
        Angle c = new Angle(1 + 1e-5);
        assertThat(a).isEqualTo(b).isNotEqualTo(c);
        assertThat(a.compareTo(c)).isNegative();
        try {
            Angle.setEpsilon(1e-9);
            assertThat(a).isNotEqualTo(b);
            assertThat(a.compareTo(b)).isNegative();
            Angle.setEpsilon(1e-4);
            assertThat(a).isEqualTo(c);
            assertThat(a.compareTo(c)).isZero();
        } finally {
            Angle.setEpsilon(Angle.DEFAULT_EPSILON);
        }
        assertThat(a).isEqualTo(b);
    }

    @Test
    void badInputGivesNaNOrIsRejected() {
        assertThat(new Angle(Double.NaN).cos()).isNaN();
        assertThat(new Angle(Double.POSITIVE_INFINITY).sin()).isNaN();
        assertThatThrownBy(() -> Angle.setEpsilon(-1)).isInstanceOf(IllegalArgumentException.class);
    }
}
