package gizmoball.stability;

import gizmoball.model.Board;
import gizmoball.model.LoopModes;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.LoopMode;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import physics.Vect;

import java.util.List;

import static org.assertj.core.api.Assertions.assertThat;

/**
 * Failure mode: zero velocity and zero dt. A ball at rest is a degenerate input to every time-until
 * method (no motion, no root); zero dt is a degenerate tick. Nothing may move, nothing may turn NaN.
 */
class ZeroVelocityTest {

    private static final double DT = Board.DEFAULT_TICK;

    /** Without gravity a ball at rest, even touching a wall or a bumper, must stay exactly where it is. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void ballsAtRestTouchingEveryKindOfSurfaceStayExactlyPut(LoopMode mode) {
        Board board = new Board();
        board.setGravity(0);
        LoopModes.set(board, mode);
        board.addGizmo(GizmoKind.SQUARE, "S", 3, 3);
        board.addGizmo(GizmoKind.CIRCLE, "C", 8, 3);
        board.addGizmo(GizmoKind.TRIANGLE, "T", 13, 3);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 3, 10);
        board.addBall("free", 10.3, 15.7, 0, 0);
        board.addBall("onWall", 0.25, 17, 0, 0);
        board.addBall("onSquareSide", 2.75, 3.5, 0, 0);
        board.addBall("onSquareCorner", 4 + 0.25 / Math.sqrt(2), 3 - 0.25 / Math.sqrt(2), 0, 0);
        board.addBall("onCircle", 8.5, 2.75, 0, 0);
        // Unrotated triangle: hypotenuse from (14,3) to (13,4), free side facing down-right.
        board.addBall("onHypotenuse", 13.5 + 0.25 / Math.sqrt(2), 3.5 + 0.25 / Math.sqrt(2), 0, 0);
        // Left flipper at rest hangs along x = 3.25 from y = 10.25 to 11.75, radius 0.25.
        board.addBall("onFlipper", 3.75, 11, 0, 0);
        List<Vect> start = positions(board);

        new Watch("balls at rest, no gravity", board, DT).run(600, (tick, b) -> {
            assertThat(positions(b)).as("tick " + tick).isEqualTo(start);
            for (BallView ball : b.balls()) {
                assertThat(ball.velocity().length()).as(ball.name() + " speed at tick " + tick).isZero();
            }
        });
    }

    /** A zero-length tick changes nothing, for balls at rest on a surface and in flight. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void zeroDtChangesNothing(LoopMode mode) {
        Board board = new Board();
        LoopModes.set(board, mode);
        board.addGizmo(GizmoKind.SQUARE, "S", 10, 10);
        board.addBall("resting", 5, Board.SIZE - 0.25, 0, 0);
        board.addBall("besideSquare", 9.75, 10.5, 0, 0);
        board.addBall("falling", 3, 3, 2, -4);
        List<Vect> start = positions(board);
        List<Vect> startVelocities = velocities(board);

        new Watch("zero dt", board, 0).run(100, (tick, b) -> {
            assertThat(positions(b)).as("positions, tick " + tick).isEqualTo(start);
            assertThat(velocities(b)).as("velocities, tick " + tick).isEqualTo(startVelocities);
            assertThat(b.time()).isZero();
        });
    }

    /** A ball released from rest under gravity falls and bounces without gaining energy beyond one tick's step. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void ballReleasedFromRestFallsAndBounces(LoopMode mode) {
        Board board = new Board();
        LoopModes.set(board, mode);
        board.addBall("B", 10, 2, 0, 0);
        double impactSpeed = Math.sqrt(2 * board.gravity() * (Board.SIZE - 0.25 - 2));
        new Watch("released from rest", board, DT).allowEnergyGainOfOneTickAt(impactSpeed).run(3000);
    }

    static List<Vect> positions(Board board) {
        return board.balls().stream().map(BallView::position).toList();
    }

    static List<Vect> velocities(Board board) {
        return board.balls().stream().map(BallView::velocity).toList();
    }
}
