package gizmoball.controller;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.RepeatedTest;
import org.junit.jupiter.api.Test;

class TickPacerTest {
    private static final long TICK_NANOS = 10_000_000L;   // 1/100 s: whole nanoseconds, no rounding in the expectations

    @Test
    void eventsHalfATickApartRunATickEverySecondEvent() {
        TickPacer pacer = new TickPacer(0.01, 4);
        int[] ticks = new int[6];
        for (int i = 0; i < ticks.length; i++) {
            ticks[i] = pacer.ticksFor(TICK_NANOS / 2);
        }

        assertThat(ticks).containsExactly(0, 1, 0, 1, 0, 1);
    }

    @Test
    void aLateEventCatchesUp() {
        TickPacer pacer = new TickPacer(0.01, 4);

        assertThat(pacer.ticksFor(3 * TICK_NANOS + 1)).isEqualTo(3);
        assertThat(pacer.ticksFor(TICK_NANOS - 2)).isZero();
        assertThat(pacer.ticksFor(1)).isEqualTo(1);
    }

    @Test
    void aStallCatchesUpAtMostTheCapAndForgetsTheRest() {
        TickPacer pacer = new TickPacer(0.01, 4);

        assertThat(pacer.ticksFor(1_000_000_000L)).isEqualTo(4);
        assertThat(pacer.ticksFor(0)).isZero();
        assertThat(pacer.ticksFor(TICK_NANOS)).isEqualTo(1);
    }

    @Test
    void aClockGoingBackwardsRunsNothing() {
        TickPacer pacer = new TickPacer(0.01, 4);

        assertThat(pacer.ticksFor(-5 * TICK_NANOS)).isZero();
        assertThat(pacer.ticksFor(TICK_NANOS)).isEqualTo(1);
    }

    /** Without stalls beyond the cap, simulated time equals real time to within one tick. */
    @RepeatedTest(20)
    void simulatedTimeFollowsRealTime(org.junit.jupiter.api.RepetitionInfo repetition) {
        long seed = 4242L + repetition.getCurrentRepetition();
        Random random = new Random(seed);
        TickPacer pacer = new TickPacer(0.01, 4);
        long real = 0;
        long ticks = 0;
        for (int i = 0; i < 1000; i++) {
            long elapsed = random.nextInt((int) (3 * TICK_NANOS));
            real += elapsed;
            ticks += pacer.ticksFor(elapsed);
            assertThat(real - ticks * TICK_NANOS).as("seed %d, event %d", seed, i).isBetween(0L, TICK_NANOS - 1);
        }
    }
}
