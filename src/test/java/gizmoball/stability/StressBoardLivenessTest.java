package gizmoball.stability;

import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.Invariants;
import gizmoball.model.loop.BallView;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;

import org.junit.jupiter.api.Test;
import physics.Vect;

import static org.assertj.core.api.Assertions.assertThat;

/**
 * boards/stress.txt (302 gizmos, 20 balls) once froze the whole board: a ball touching a surface at a closing
 * speed below the last digit of its velocity was resolved at zero time again and again without any velocity
 * changing, until the tick's collision limit ended the tick for every ball (from tick 2,346 on, for good).
 * Here every free ball that keeps a clear speed must keep moving: a ball resting on a surface loses its normal
 * velocity (at most a tangential one is left, and it slides), a wedged one is stopped, so a ball that ends tick
 * after tick at the same place with a speed of over 1 L/s is one the loop no longer moves.
 */
class StressBoardLivenessTest {
    private static final double DT = 1.0 / 60;
    private static final int TICKS = 3000;
    /** Well above the resting-contact speed (two ticks of gravity, 0.83 L/s at 25 L/s^2): a ball with this moves. */
    private static final double CLEAR_SPEED = 1.0;
    /** Consecutive ticks at the same place with a clear speed that make a ball frozen (one may be a wedge). */
    private static final int FROZEN_TICKS = 3;
    /** Ticks by which every ball of the board lies asleep (it took 12,000, 200 s). */
    private static final int SETTLED = 16_000;

    /**
     * And it settles: friction and lossy bounces take energy and nothing gives any, so no ball rocks for ever. One
     * ball once did, from tick 14,000 on: in the wedge between a resting flipper's round end and a triangle's slope,
     * the timing of each bounce off the flipper, early in a tick, gave it more than the bounce and friction took.
     */
    @Test
    void everyBallIsAsleepBySixteenThousandTicks() throws Exception {
        Board board = BoardFiles.load(Path.of("boards", "stress.txt"));
        for (int tick = 1; tick <= SETTLED; tick++) {
            board.tick(DT);
        }
        assertThat(board.balls()).filteredOn(ball -> !ball.isCaptured() && !ball.isAsleep()).isEmpty();
    }

    @Test
    void everyBallWithAClearSpeedKeepsMovingForThreeThousandTicks() throws Exception {
        Board board = BoardFiles.load(Path.of("boards", "stress.txt"));
        Map<String, Vect> lastPosition = new HashMap<>();
        Map<String, Integer> stillTicks = new HashMap<>();
        for (int tick = 1; tick <= TICKS; tick++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", tick).isEmpty();
            for (BallView ball : board.balls()) {
                Vect before = lastPosition.put(ball.name(), ball.position());
                boolean frozen = !ball.isCaptured() && ball.position().equals(before)
                        && ball.velocity().length() > CLEAR_SPEED;
                int still = frozen ? stillTicks.merge(ball.name(), 1, Integer::sum) : 0;
                stillTicks.put(ball.name(), still);
                assertThat(still).as("tick %d: %s has not moved for %d ticks", tick, ball, still)
                        .isLessThan(FROZEN_TICKS);
            }
        }
    }
}
