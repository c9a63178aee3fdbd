package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

class DecimalsTest {
    private static final long SEED = 20261130L;

    @ParameterizedTest
    @CsvSource({"7, 7.0", "0, 0.0", "-3, -3.0", "0.5, 0.5", "18.25, 18.25", "0.00001, 0.00001",
                "123456789012, 123456789012.0", "1e20, 100000000000000000000.0"})
    void formatsPlainDecimals(double value, String expected) {
        assertThat(Decimals.format(value)).isEqualTo(expected);
    }

    @Test
    void negativeZeroKeepsItsSign() {
        assertThat(Decimals.format(-0.0)).isEqualTo("-0.0");
        assertThat(Double.doubleToRawLongBits(Decimals.parse("-0.0").getAsDouble()))
                .isEqualTo(Double.doubleToRawLongBits(-0.0));
    }

    @Test
    void everyFormattedDoubleReadsBackToTheSameBits() {
        Random random = new Random(SEED);
        for (int i = 0; i < 10_000; i++) {
            double value = switch (i % 4) {
                case 0 -> random.nextDouble() * 20;
                case 1 -> (random.nextDouble() - 0.5) * 400;
                case 2 -> Double.longBitsToDouble(random.nextLong());
                default -> random.nextInt(41) / 2.0;
            };
            if (!Double.isFinite(value)) {
                continue;
            }
            String text = Decimals.format(value);
            assertThat(text).as("seed %d case %d value %s", SEED, i, value).doesNotContain("E", "e")
                    .contains(".");
            assertThat(Decimals.parse(text).getAsDouble()).as("seed %d case %d: %s", SEED, i, text)
                    .isEqualTo(value);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"7", "7.0", "-7.", ".5", "+2.5", "1e3", "2.5E-2"})
    void readsDecimalNotation(String word) {
        assertThat(Decimals.parse(word)).hasValue(Double.parseDouble(word));
    }

    @ParameterizedTest
    @ValueSource(strings = {"NaN", "Infinity", "-Infinity", "0x1p3", "1d", "2f", "1e400", "", ".", "1,5", "7.0.0", "abc"})
    void refusesWhatIsNotAFiniteDecimal(String word) {
        assertThat(Decimals.parse(word)).isEmpty();
    }

    @Test
    void refusesToWriteNonFiniteNumbers() {
        assertThatThrownBy(() -> Decimals.format(Double.NaN)).isInstanceOf(IllegalArgumentException.class);
    }
}
