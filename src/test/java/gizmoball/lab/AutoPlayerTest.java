package gizmoball.lab;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.game.KeyPress;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The autoplayer flips at a ball falling into a flipper's swept area and not at one falling past out of reach, and
 * only through the board's keys. A left flipper at (6, 16) pivots at (6.25, 16.25) and sweeps the quarter disc below
 * and right of the pivot, out to 1.5 L (pivot to tip) + 0.25 (round end) + 0.25 (ball) = 2 L.
 */
class AutoPlayerTest {
    private static final int Z = 90;
    private static final int SEEDS = 50;
    private static final String FLIPPER = """
            LeftFlipper LF 6 16
            KeyConnect key 90 down LF
            KeyConnect key 90 up LF
            """;

    /** The presses of Z by an autoplayer seeded {@code seed} in the first two seconds of the board. */
    private static List<KeyPress> zPresses(String ball, long seed) throws Exception {
        Board board = BoardFiles.load("test", FLIPPER + ball);
        Player player = new AutoPlayer(board, Board.DEFAULT_TICK, new SplittableRandom(seed));
        for (int tick = 0; tick < 120; tick++) {
            player.beforeTick(board);
            board.tick(Board.DEFAULT_TICK);
        }
        return board.game().keys().stream()
                .filter(k -> k.keyCode() == Z && k.motion() == KeyPress.Motion.DOWN).toList();
    }

    @Test
    void flipsAtABallFallingIntoTheFlippersReach() throws Exception {
        // Dropped from rest at x = 7.25, 1 L right of the pivot: its centre is in the swept area while it is below
        // the pivot (y >= 16.25) and within 2 L of it (y <= 16.25 + sqrt(3)), from sqrt(2 * 4.25 / 25) = 0.583 s
        // to sqrt(2 * 5.982 / 25) = 0.692 s: ticks 35 to 41. A press may come a swing (6 ticks) before, and up to
        // 5 ticks late: from tick 29 to tick 46. (After, the ball bounces off the floor and comes back.)
        int flippedInTime = 0;
        for (long seed = 1; seed <= SEEDS; seed++) {
            List<KeyPress> presses = zPresses("Ball B 7.25 12 0 0\n", seed);
            if (!presses.isEmpty() && presses.get(0).tick() >= 29 && presses.get(0).tick() <= 46) {
                flippedInTime++;
            }
        }
        // It misses a ball in reach with a chance of 4 %: at least 44 of 50 is 3 deviations below the 48 expected.
        assertThat(flippedInTime).isGreaterThanOrEqualTo(44);
    }

    @Test
    void doesNotFlipAtABallFallingOutOfReach() throws Exception {
        for (long seed = 1; seed <= SEEDS; seed++) {
            // Left of the pivot: the swing goes the other way. Right of it by 2.5 L: beyond the tip's reach.
            assertThat(zPresses("Ball B 5 12 0 0\n", seed)).as("seed %d, left of the pivot", seed).isEmpty();
            assertThat(zPresses("Ball B 8.75 12 0 0\n", seed)).as("seed %d, beyond the tip", seed).isEmpty();
        }
    }
}
