package gizmoball.stability;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.LoopModes;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.LoopMode;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import static org.assertj.core.api.Assertions.assertThat;

/**
 * Failure mode: a ball between a flipper and a wall. A left flipper at (5,17) swings up (pivot (5.25,17.25),
 * tip from (5.25,18.75) to (6.75,17.25)) into the corner formed by a square above its box, at (6,16), and
 * a square right of it, at (7,17): at the end of the swing the bar touches both, so a ball caught there is
 * squeezed between a rotating surface and two static ones. Also a ball rolling on the floor under a
 * flipper whose bar reaches down to the floor. The ball must never end up inside anything.
 */
class FlipperPinchTest {

    private static final double DT = Board.DEFAULT_TICK;
    private static final double R = Board.BALL_RADIUS;
    private static final int KEY = 32;

    static Stream<Arguments> ballsInTheSweep() {
        List<Arguments> cases = new ArrayList<>();
        double[][] starts = {{5.9, 17.55}, {6.3, 17.55}, {6.72, 17.3}, {6.3, 18.0}, {6.6, 18.5}, {5.9, 18.3}};
        for (LoopMode mode : LoopMode.values()) {
            for (double gravity : new double[] {0, Board.DEFAULT_GRAVITY}) {
                for (double[] s : starts) {
                    cases.add(Arguments.of(mode, gravity, s[0], s[1]));
                }
            }
        }
        return cases.stream();
    }

    @ParameterizedTest(name = "{0}, gravity {1}, ball at ({2}, {3})")
    @MethodSource("ballsInTheSweep")
    void flipperSwingingIntoACornerWithABallInTheWay(LoopMode mode, double gravity, double x, double y) {
        Board board = new Board();
        LoopModes.set(board, mode);
        board.setGravity(gravity);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 5, 17);
        board.addGizmo(GizmoKind.SQUARE, "Above", 6, 16);
        board.addGizmo(GizmoKind.SQUARE, "Right", 7, 17);
        board.bindKey(KEY, KeyEdge.DOWN, "F");
        board.bindKey(KEY, KeyEdge.UP, "F");
        board.addBall("B", x, y, 0, 0);
        board.keyDown(KEY);
        String name = "pinch " + mode + " g=" + gravity + " ball at (" + x + ", " + y + ")";
        new Watch(name, board, DT).energyMayGrow().run(200, (tick, b) -> {
            assertOutsideFlipper(b, tick);
            if (tick == 60) {
                b.keyUp(KEY);
            }
            if (tick == 120) {
                b.keyDown(KEY);
            }
        });
    }

    static Stream<Arguments> pressTimes() {
        List<Arguments> cases = new ArrayList<>();
        for (LoopMode mode : LoopMode.values()) {
            for (int pressTick : new int[] {10, 30, 38, 42, 46, 50, 54, 58, 70}) {
                cases.add(Arguments.of(mode, pressTick));
            }
        }
        return cases.stream();
    }

    /** Flipper at (5,18): its resting bar reaches the floor; a ball rolls in along the floor under its sweep. */
    @ParameterizedTest(name = "{0}, key down at tick {1}")
    @MethodSource("pressTimes")
    void flipperSwingingOverABallOnTheFloor(LoopMode mode, int pressTick) {
        Board board = new Board();
        LoopModes.set(board, mode);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 5, 18);
        board.bindKey(KEY, KeyEdge.DOWN, "F");
        board.bindKey(KEY, KeyEdge.UP, "F");
        board.addBall("B", 8.5, Board.SIZE - R, -3, 0);
        new Watch("floor pinch " + mode + " press at " + pressTick, board, DT)
                .energyMayGrow().run(250, (tick, b) -> {
                    assertOutsideFlipper(b, tick);
                    if (tick == pressTick) {
                        b.keyDown(KEY);
                    }
                    if (tick == pressTick + 40) {
                        b.keyUp(KEY);
                    }
                });
    }

    /** Our own check, independent of the model's Invariants: the ball clears the flipper's capsule. */
    private static void assertOutsideFlipper(Board board, int tick) {
        FlipperView f = (FlipperView) board.gizmo("F").orElseThrow();
        for (BallView ball : board.balls()) {
            if (!ball.isCaptured()) {
                assertThat(Shapes.toSegment(f.pivot(), f.tip(), ball.position()))
                        .as("ball centre to flipper axis at tick " + tick + " (angle " + f.angleFromRest() + ", ball at "
                                + ball.position() + ")")
                        .isGreaterThanOrEqualTo(f.radius() + R - 1e-6);
            }
        }
    }
}
