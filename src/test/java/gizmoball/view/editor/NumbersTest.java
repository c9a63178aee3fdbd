package gizmoball.view.editor;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import static org.assertj.core.api.Assertions.assertThat;

class NumbersTest {
    @Test
    void numbersReadAsTyped() {
        assertThat(Numbers.exact(25.0)).isEqualTo("25");
        assertThat(Numbers.exact(0.025)).isEqualTo("0.025");
        assertThat(Numbers.exact(-3.5)).isEqualTo("-3.5");
        assertThat(Numbers.brief(3.14159)).isEqualTo("3.14");
        assertThat(Numbers.brief(-4.0)).isEqualTo("-4");
    }

    @ParameterizedTest
    @ValueSource(doubles = {0.1, 1.0 / 3, 19.75, 1e-7, 123456.789, -0.30000000000000004})
    void exactTextReadsBackAsTheSameNumber(double v) {
        assertThat(Double.parseDouble(Numbers.exact(v))).isEqualTo(v);
    }
}
