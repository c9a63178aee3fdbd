package gizmoball.stability;

import gizmoball.model.Board;
import gizmoball.model.LoopModes;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.LoopMode;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

/**
 * Failure mode: balls touching when the board is loaded. Their distance is exactly two radii, so every
 * time-until method sits on its boundary case: touching and closing is a collision now, touching and
 * separating or at rest is none, and nothing may explode, stick or overlap.
 */
class TouchingBallsTest {

    private static final double DT = Board.DEFAULT_TICK;
    private static final double R = Board.BALL_RADIUS;

    /** Touching and closing head-on: equal masses swap velocities at once, in the first tick. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void touchingAndClosingSwapVelocitiesInTheFirstTick(LoopMode mode) {
        Board board = FreeSpace.board(mode);
        board.addBall("left", 10 - R, 10, 4, 0);
        board.addBall("right", 10 + R, 10, -4, 0);
        new Watch("touching head-on", board, DT).run(1);
        assertThat(board.balls().get(0).velocity().x()).isCloseTo(-4, within(1e-9));
        assertThat(board.balls().get(1).velocity().x()).isCloseTo(4, within(1e-9));
        new Watch("touching head-on, afterwards", board, DT).run(200);
    }

    /** Touching and separating: no collision, both fly apart untouched. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void touchingAndSeparatingFlyApartUntouched(LoopMode mode) {
        Board board = FreeSpace.board(mode);
        board.addBall("left", 10 - R, 10, -3, 1);
        board.addBall("right", 10 + R, 10, 3, -1);
        // 60 ticks = 1 s: 3 L each way, no wall reached.
        new Watch("touching, separating", board, DT).run(60, (tick, b) -> {
            assertThat(b.balls().get(0).velocity().x()).as("left vx at tick " + tick).isEqualTo(-3);
            assertThat(b.balls().get(1).velocity().x()).as("right vx at tick " + tick).isEqualTo(3);
        });
    }

    /**
     * Side by side and stacked on the floor under gravity: no overlap in either loop; in the game's loop
     * no ball ever moves faster than two ticks of gravity.
     */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void touchingBallsAtRestOnTheFloorStayPut(LoopMode mode) {
        Board board = new Board();
        LoopModes.set(board, mode);
        double floor = Board.SIZE - R;
        board.addBall("a", 5, floor, 0, 0);
        board.addBall("b", 5 + 2 * R, floor, 0, 0);
        board.addBall("c", 5 + 4 * R, floor, 0, 0);
        board.addBall("stackBottom", 15, floor, 0, 0);
        board.addBall("stackTop", 15, floor - 2 * R, 0, 0);
        double g = board.gravity();
        new Watch("touching at rest on the floor", board, DT).allowEnergyGainOfOneTickAt(4 * g * DT).run(600, (tick, b) -> {
            if (mode == LoopMode.SEED) {
                return;   // one collision per tick: the other resting balls fall for that tick (see Watch)
            }
            for (BallView ball : b.balls()) {
                assertThat(ball.velocity().length()).as(ball.name() + " speed at tick " + tick)
                        .isLessThanOrEqualTo(2 * g * DT + 1e-9);
            }
        });
    }

    /** A row of three touching balls driven into a wall: a Newton's cradle, again and again. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void touchingRowDrivenIntoAWall(LoopMode mode) {
        Board board = FreeSpace.board(mode);
        board.addBall("a", 15, 10, 7, 0);
        board.addBall("b", 15 + 2 * R, 10, 7, 0);
        board.addBall("c", 15 + 4 * R, 10, 7, 0);
        double e0 = board.energy();
        new Watch("touching row into a wall", board, DT).run(600,
                (tick, b) -> assertThat(b.energy()).as("energy at tick " + tick).isCloseTo(e0, within(1e-9 * e0)));
    }
}
