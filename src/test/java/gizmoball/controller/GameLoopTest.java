package gizmoball.controller;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import org.junit.jupiter.api.Test;

/** The loop with its pulse and clock driven by hand: each event runs the ticks that the time since the last owes. */
class GameLoopTest {
    private static final double DT = Board.DEFAULT_TICK;
    private static final long TICK_NANOS = Math.round(DT * 1e9);
    private final Board board = new Board();
    private final HandPulse pulse = new HandPulse();
    private long nanos = 1_000_000_000L;
    private final GameLoop loop = new GameLoop(board, DT, pulse, () -> nanos);

    @Test
    void stepRunsExactlyOneTick() {
        loop.step();
        assertThat(board.time()).isEqualTo(DT);
        loop.step();
        assertThat(board.time()).isEqualTo(DT + DT);
        assertThat(loop.isRunning()).isFalse();
    }

    @Test
    void thePulseComesTwiceATick() {
        assertThat(pulse.periodMillis).isEqualTo((int) (DT * 1000 / 2));
    }

    @Test
    void startTicksOnEveryEventUntilStop() {
        int[] runningChanges = new int[1];
        loop.addRunningListener(() -> runningChanges[0]++);

        loop.start();
        loop.start();
        assertThat(loop.isRunning()).isTrue();
        assertThat(runningChanges[0]).as("a second start changes nothing").isEqualTo(1);
        nanos += TICK_NANOS / 2;
        pulse.fire();
        assertThat(board.time()).as("half a tick owed").isZero();
        nanos += TICK_NANOS - TICK_NANOS / 2 + 2 * TICK_NANOS;
        pulse.fire();
        assertThat(board.time()).as("three ticks owed").isEqualTo(DT + DT + DT);

        loop.stop();
        double stoppedAt = board.time();
        nanos += 10 * TICK_NANOS;
        pulse.fire();
        assertThat(board.time()).as("no tick once stopped").isEqualTo(stoppedAt);
        assertThat(runningChanges[0]).isEqualTo(2);
        assertThat(loop.isRunning()).isFalse();
    }

    /** Issue 23, item 9: at 1/8x a tick comes every 8th of a second, but a view is told every timer event. */
    @Test
    void inSlowMotionEveryTimerEventTellsHowFarTheNextTickHasComeWithoutTicking() {
        java.util.List<Double> fractions = new java.util.ArrayList<>();
        loop.addFrameListener(fractions::add);
        loop.setSpeed(Speed.EIGHTH);
        long eighthOfATick = Math.round(DT / Speed.EIGHTH.factor() / 8 * 1e9);

        for (int i = 0; i < 7; i++) {
            loop.elapsed(eighthOfATick);
        }

        assertThat(board.time()).as("no tick yet").isZero();
        assertThat(fractions).hasSize(7);
        for (int i = 0; i < 7; i++) {
            assertThat(fractions.get(i)).isCloseTo((i + 1) / 8.0, org.assertj.core.data.Offset.offset(1e-6));
        }
        loop.elapsed(eighthOfATick);
        assertThat(board.time()).as("the tick, on time").isEqualTo(DT);
        assertThat(fractions.get(7)).isCloseTo(0, org.assertj.core.data.Offset.offset(1e-6));
    }

    @Test
    void atFullSpeedOnlyEventsThatTickTellTheViewAndStoppingTellsItToDrawTheLastTick() {
        java.util.List<Double> fractions = new java.util.ArrayList<>();
        loop.addFrameListener(fractions::add);
        long halfATick = Math.round(DT / 2 * 1e9);

        loop.elapsed(halfATick);
        assertThat(fractions).isEmpty();
        loop.elapsed(halfATick + 1);
        assertThat(fractions).hasSize(1);
        loop.stop();
        assertThat(fractions.get(fractions.size() - 1)).isEqualTo(1.0);
    }

    @Test
    void timeStoppedIsNotOwedOnRestart() {
        loop.start();
        loop.stop();
        nanos += 60 * TICK_NANOS;
        loop.start();
        nanos += TICK_NANOS;
        pulse.fire();
        assertThat(board.time()).isEqualTo(DT);
    }

    /** The loop's pulse, sent by the test: like a stopped Swing Timer, it sends nothing while stopped. */
    private static final class HandPulse implements GameLoop.PulseSource, GameLoop.Pulse {
        private Runnable event;
        private int periodMillis;
        private boolean running;

        @Override
        public GameLoop.Pulse every(int period, Runnable onEvent) {
            periodMillis = period;
            event = onEvent;
            return this;
        }

        @Override
        public void start() {
            running = true;
        }

        @Override
        public void stop() {
            running = false;
        }

        @Override
        public boolean isRunning() {
            return running;
        }

        void fire() {
            if (running) {
                event.run();
            }
        }
    }
}
