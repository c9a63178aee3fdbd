package gizmoball.stability;

import gizmoball.model.Board;
import gizmoball.model.LoopModes;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.LoopMode;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

/**
 * Failure mode (docs/design.md, "Failure modes": resting contact): a ball resting on, or moving parallel to, a surface. Under gravity it gets a
 * collision at time 0 every tick; it must neither sink, nor hop higher than one tick of gravity can lift
 * it, nor freeze the loop, nor gain energy.
 */
class RestingContactTest {

    private static final double DT = Board.DEFAULT_TICK;
    private static final double R = Board.BALL_RADIUS;

    /** No overlap in either loop; in the game's loop the balls also stay within one tick's hop, slowly. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void ballsRestOnTheFloorASquareAndATriangleTop(LoopMode mode) {
        Board board = new Board();
        LoopModes.set(board, mode);
        board.addGizmo(GizmoKind.SQUARE, "S", 5, 12);
        board.addGizmo(GizmoKind.TRIANGLE, "T", 12, 12);   // unrotated: flat top edge from (12,12) to (13,12)
        board.addBall("onFloor", 10.5, Board.SIZE - R, 0, 0);
        board.addBall("onSquare", 5.5, 12 - R, 0, 0);
        board.addBall("onTriangle", 12.3, 12 - R, 0, 0);
        double[] restY = {Board.SIZE - R, 12 - R, 12 - R};
        double hop = board.gravity() * DT * DT;

        new Watch("resting on floor, square, triangle", board, DT)
                .allowEnergyGainOfOneTickAt(board.gravity() * DT)
                .run(3000, (tick, b) -> {
                    if (mode == LoopMode.SEED) {
                        return;   // one collision per tick: the other resting balls fall for that tick (see Watch)
                    }
                    for (int i = 0; i < restY.length; i++) {
                        BallView ball = b.balls().get(i);
                        assertThat(ball.position().y()).as(ball.name() + " height at tick " + tick)
                                .isBetween(restY[i] - hop - 1e-9, restY[i] + 1e-6);
                        assertThat(ball.velocity().length()).as(ball.name() + " speed at tick " + tick)
                                .isLessThanOrEqualTo(b.gravity() * DT + 1e-9);
                    }
                });
    }

    /** Rolling along the floor: the height stays on the floor and nothing kicks the ball upward. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void ballRollingAlongTheFloorStaysOnIt(LoopMode mode) {
        Board board = new Board();
        LoopModes.set(board, mode);
        board.addBall("roller", 2, Board.SIZE - R, 8, 0);
        double hop = board.gravity() * DT * DT;
        new Watch("rolling along the floor", board, DT)
                .allowEnergyGainOfOneTickAt(board.gravity() * DT)
                .run(1200, (tick, b) -> {
                    BallView ball = b.balls().get(0);
                    assertThat(ball.position().y()).as("height at tick " + tick)
                            .isBetween(Board.SIZE - R - hop - 1e-9, Board.SIZE - R + 1e-6);
                    assertThat(Math.abs(ball.velocity().y())).as("vertical speed at tick " + tick)
                            .isLessThanOrEqualTo(b.gravity() * DT + 1e-9);
                });
    }

    /** Without gravity a ball gliding along a wall, touching it, is not deflected at all. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void ballGlidingAlongAWallIsNotDeflected(LoopMode mode) {
        Board board = FreeSpace.board(mode);
        board.addBall("glider", R, 1, 0, 9);
        // 120 ticks: 18 L down the wall, short of the floor.
        new Watch("gliding along the left wall", board, DT).run(120, (tick, b) -> {
            BallView ball = b.balls().get(0);
            assertThat(ball.position().x()).as("distance from the wall at tick " + tick).isCloseTo(R, within(1e-12));
            assertThat(ball.velocity().x()).as("sideways speed at tick " + tick).isCloseTo(0, within(1e-12));
        });
    }
}
