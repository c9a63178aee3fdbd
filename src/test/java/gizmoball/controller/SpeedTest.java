package gizmoball.controller;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.loop.BallView;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Game > Speed: the clock changes, the physics does not. The loop is fed real-time intervals directly. */
class SpeedTest {
    private static final double DT = Board.DEFAULT_TICK;
    /** What the loop's timer delivers: an event every 8 ms. */
    private static final long EVENT_NANOS = 8_000_000;

    @Test
    void aSpeedTicksThatManyTimesAsOftenAsRealTimeAtOneX() throws Exception {
        for (Speed speed : Speed.values()) {
            Board board = BoardFiles.load(Path.of("boards", "default.txt"));
            int[] ticked = new int[1];
            board.addObserver((b, change) -> ticked[0]++);
            GameLoop loop = new GameLoop(board, DT);
            loop.setSpeed(speed);
            long tenSeconds = 10_000_000_000L;
            for (long t = 0; t < tenSeconds; t += EVENT_NANOS) {
                loop.elapsed(EVENT_NANOS);
            }
            // 10 s of real time is 10 * factor simulated seconds, 600 * factor ticks, less the one still owed.
            int expected = (int) Math.round(600 * speed.factor());
            assertThat(ticked[0]).as(speed.label()).isBetween(expected - 1, expected);
        }
    }

    @Test
    void theSameNumberOfTicksGivesTheSamePositionsAtEverySpeed() throws Exception {
        List<BallView> atOneX = ballsAfter(600, Speed.NORMAL);
        for (Speed speed : Speed.values()) {
            List<BallView> balls = ballsAfter(600, speed);
            assertThat(balls).hasSameSizeAs(atOneX);
            for (int i = 0; i < balls.size(); i++) {
                assertThat(balls.get(i).position()).as(speed.label()).isEqualTo(atOneX.get(i).position());
                assertThat(balls.get(i).velocity()).as(speed.label()).isEqualTo(atOneX.get(i).velocity());
            }
        }
    }

    /** Plays multiball.txt at {@code speed} until {@code ticks} ticks have run, as the timer would. */
    private static List<BallView> ballsAfter(int ticks, Speed speed) throws Exception {
        Board board = BoardFiles.load(Path.of("boards", "multiball.txt"));
        int[] ticked = new int[1];
        board.addObserver((b, change) -> ticked[0]++);
        GameLoop loop = new GameLoop(board, DT);
        loop.setSpeed(speed);
        long realNanos = 0;
        while (ticked[0] < ticks) {
            loop.elapsed(EVENT_NANOS);
            realNanos += EVENT_NANOS;
        }
        assertThat(ticked[0]).isEqualTo(ticks);
        assertThat(realNanos / 1e9).as("real seconds at " + speed.label())
                .isBetween(ticks * DT / speed.factor() - 0.01, ticks * DT / speed.factor() + 0.01);
        return board.balls();
    }
}
