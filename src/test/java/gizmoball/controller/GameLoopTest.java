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
}
