package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class FpsMeterTest {
    private static final long SECOND = 1_000_000_000L;

    @Test
    void countsTheFramesOfTheLastSecond() {
        FpsMeter meter = new FpsMeter();
        for (int i = 0; i < 120; i++) {
            meter.frame(i * SECOND / 60);
        }
        long lastFrame = 119 * SECOND / 60;

        assertThat(meter.fps(lastFrame)).isEqualTo(60);
    }

    @Test
    void dropsToZeroWhenNothingIsPainted() {
        FpsMeter meter = new FpsMeter();
        for (int i = 0; i < 30; i++) {
            meter.frame(i * SECOND / 30);
        }

        assertThat(meter.fps(29 * SECOND / 30)).isEqualTo(30);
        assertThat(meter.fps(29 * SECOND / 30 + SECOND)).isZero();
    }
}
