package gizmoball.controller;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.fail;

import gizmoball.model.Board;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/** The loop's Swing Timer needs no display: these run headless. */
class GameLoopTest {
    private static final double DT = Board.DEFAULT_TICK;
    private final Board board = new Board();
    private final GameLoop loop = new GameLoop(board, DT);

    private static <T> T onEdt(java.util.function.Supplier<T> read) throws Exception {
        AtomicReference<T> result = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> result.set(read.get()));
        return result.get();
    }

    @Test
    void stepRunsExactlyOneTick() {
        loop.step();
        assertThat(board.time()).isEqualTo(DT);
        loop.step();
        assertThat(board.time()).isEqualTo(DT + DT);
        assertThat(loop.isRunning()).isFalse();
    }

    @Test
    void startTicksOnTheEventThreadUntilStop() throws Exception {
        Thread[] tickThread = new Thread[1];
        board.addObserver((b, change) -> tickThread[0] = Thread.currentThread());
        int[] runningChanges = new int[1];
        loop.addRunningListener(() -> runningChanges[0]++);

        SwingUtilities.invokeAndWait(() -> {
            loop.start();
            loop.start();
        });
        long deadline = System.currentTimeMillis() + 5000;
        while (onEdt(board::time) < 5 * DT) {
            if (System.currentTimeMillis() > deadline) {
                fail("the loop did not tick");
            }
            Thread.sleep(10);
        }
        SwingUtilities.invokeAndWait(loop::stop);
        double stoppedAt = onEdt(board::time);
        Thread.sleep(100);

        assertThat(onEdt(board::time)).isEqualTo(stoppedAt);
        assertThat(tickThread[0].getName()).startsWith("AWT-EventQueue");
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
}
