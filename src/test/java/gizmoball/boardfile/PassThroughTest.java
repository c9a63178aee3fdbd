package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.Board;
import gizmoball.model.loop.BallView;
import org.junit.jupiter.api.Test;

/**
 * Two balls a file placed on each other pass through each other until they no longer overlap, then collide as
 * usual. In free space (no gravity, no friction) the motion is exact: straight lines at constant velocity.
 */
class PassThroughTest {
    private static final double DT = Board.DEFAULT_TICK;

    @Test
    void anOverlappingPairClosingOnEachOtherCrossesWithoutABounce() throws BoardFileException {
        // 0.2 L apart, closing at 2 L/s: they cross, and are 0.5 L apart (touching) on the other side after 0.35 s.
        Board board = BoardFiles.load("f", "Gravity 0\nFriction 0 0\nBall A 10 10 1 0\nBall B 10.2 10 -1 0\n");
        for (int tick = 0; tick < 60; tick++) {
            board.tick(DT);
        }
        BallView a = board.ball("A").orElseThrow();
        BallView b = board.ball("B").orElseThrow();
        assertThat(a.velocity().x()).isEqualTo(1);
        assertThat(b.velocity().x()).isEqualTo(-1);
        assertThat(a.position().x()).isCloseTo(11, within(1e-9));
        assertThat(b.position().x()).isCloseTo(9.2, within(1e-9));
    }

    @Test
    void aPairThatHasSeparatedCollidesAsUsual() throws BoardFileException {
        // Overlapping and separating at 2 L/s: apart after 0.15 s; the walls at 0 and 20 send them back, and
        // they meet head-on at x = 10 and bounce (equal masses swap velocities) instead of crossing again.
        Board board = BoardFiles.load("f", "Gravity 0\nFriction 0 0\nBall A 9.9 10 -4 0\nBall B 10.1 10 4 0\n");
        double closest = Double.POSITIVE_INFINITY;
        boolean separated = false;
        for (int tick = 0; tick < 6 * 60; tick++) {
            board.tick(DT);
            double distance = Math.sqrt(board.ball("A").orElseThrow().position()
                    .distanceSquared(board.ball("B").orElseThrow().position()));
            separated |= distance >= 2 * Board.BALL_RADIUS;
            if (separated) {
                closest = Math.min(closest, distance);
            }
        }
        assertThat(separated).isTrue();
        assertThat(closest).as("once apart they never overlap again").isGreaterThan(2 * Board.BALL_RADIUS - 1e-6);
    }
}
