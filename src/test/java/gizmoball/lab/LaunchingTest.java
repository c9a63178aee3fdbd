package gizmoball.lab;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.game.KeyPress;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * Both players launch a ball waiting in an absorber with the key bound to it, holding the key between 0.1 and 1.5 s
 * of board time (a plunger fires harder the longer), another hold for another seed; the idle player never flips.
 */
class LaunchingTest {
    private static final int SPACE = 32;
    private static final String BOARD = """
            Absorber A 0 19 20 20
            LeftFlipper LF 6 16
            KeyConnect key 90 down LF
            KeyConnect key 90 up LF
            KeyConnect key 32 down A
            Ball B 19.75 19.75 0 0
            """;

    private static List<KeyPress> keys(PlayerKind kind, long seed) throws Exception {
        Board board = BoardFiles.load("test", BOARD);
        Player player = kind.create(board, Board.DEFAULT_TICK, seed);
        for (int tick = 0; tick < 180; tick++) {
            player.beforeTick(board);
            board.tick(Board.DEFAULT_TICK);
        }
        return board.game().keys();
    }

    @Test
    void eachPlayerHoldsTheLaunchKeyForASeededTimeBetweenATenthAndOneAndAHalfSeconds() throws Exception {
        for (PlayerKind kind : PlayerKind.values()) {
            Set<Long> holds = new HashSet<>();
            for (long seed = 1; seed <= 20; seed++) {
                List<KeyPress> space = keys(kind, seed).stream().filter(k -> k.keyCode() == SPACE).toList();
                assertThat(space).as("%s seed %d", kind, seed).hasSizeGreaterThanOrEqualTo(2);
                assertThat(space.get(0).motion()).isEqualTo(KeyPress.Motion.DOWN);
                assertThat(space.get(1).motion()).isEqualTo(KeyPress.Motion.UP);
                // It waits 0.2 to 1 s before pressing: 12 to 60 ticks.
                assertThat(space.get(0).tick()).isBetween(12L, 60L);
                long held = space.get(1).tick() - space.get(0).tick();
                assertThat(held).isBetween(6L, 90L);
                holds.add(held);
            }
            assertThat(holds).as("%s: the holds of 20 seeds", kind).hasSizeGreaterThan(5);
        }
    }

    @Test
    void theIdlePlayerNeverFlips() throws Exception {
        for (long seed = 1; seed <= 20; seed++) {
            assertThat(keys(PlayerKind.IDLE, seed)).extracting(KeyPress::keyCode).containsOnly(SPACE);
        }
    }
}
