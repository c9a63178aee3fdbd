package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.GuardCounts;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.api.Test;

import physics.Vect;

/**
 * Three cases where the loop's old guards were wrong physics (docs/design.md, "Guards"), checked against closed forms
 * at dt = 1/60 s: a ball at a flipper's pivot end, a slow ball meeting a vertical wall, and the tangential speed of a
 * ball bouncing on the floor.
 */
class LoopReproductionsTest {
    private static final double DT = 1.0 / 60;
    /** 1080 degrees per second in radians. */
    private static final double OMEGA = Math.toRadians(1080);

    private static Board flipperWithBall(GizmoKind kind, double leftX, double y) {
        Board board = new Board();
        board.addGizmo(kind, "F", 8, 8);
        // a right flipper mirrors a left one about the box's vertical centre line x = 9
        double x = kind == GizmoKind.LEFT_FLIPPER ? leftX : 18 - leftX;
        board.addBall("B", x, y, 0, 0);
        board.bindKey(90, KeyEdge.DOWN, "F");
        board.setGravity(0);
        board.setFriction(0, 0);
        return board;
    }

    /**
     * Pivot (8.25, 8.25); the ball's centre 0.5 L above it touches the round pivot end (radius 0.25 + 0.25) at every
     * angle, and the bar sweeps from hanging down to pointing right, never up: nothing ever pushes the ball. The
     * swing of 90 degrees at 1080 degrees/s takes 1/12 s, exactly 5 ticks.
     */
    @ParameterizedTest
    @EnumSource(value = GizmoKind.class, names = {"LEFT_FLIPPER", "RIGHT_FLIPPER"})
    void aBallAtThePivotEndLeavesTheSwingAlone(GizmoKind kind) {
        Board board = flipperWithBall(kind, 8.25, 7.75);
        Vect start = board.ball("B").orElseThrow().position();
        board.keyDown(90);
        FlipperView flipper = (FlipperView) board.gizmo("F").orElseThrow();
        for (int tick = 1; tick <= 5; tick++) {
            board.tick(DT);
            assertThat(flipper.angleFromRest()).as("tick %d", tick).isCloseTo(18.0 * tick, within(1e-9));
        }
        assertThat(flipper.angleFromRest()).isEqualTo(90.0);
        BallView ball = board.ball("B").orElseThrow();
        assertThat(ball.position()).isEqualTo(start);
        assertThat(ball.velocity()).isEqualTo(Vect.ZERO);
        assertThat(board.guardsFired()).isEqualTo(GuardCounts.NONE);
    }

    /**
     * The ball touches the pivot end 10 degrees above the line the bar ends on; the bar's side reaches it at 10
     * degrees of swing with the contact at the pivot end, then pushes it outward. The flipper must still reach its
     * stop on time (tick 5) and the ball leave faster than the slowest pushing point (0.5 L from the pivot, at
     * omega 0.5) and no faster than the fastest point that can bat it, the tip end's centre 1.5 L out, with the
     * coefficient 0.95 ((1 + 0.95) omega 1.5).
     */
    @ParameterizedTest
    @EnumSource(value = GizmoKind.class, names = {"LEFT_FLIPPER", "RIGHT_FLIPPER"})
    void aBallTouchingThePivotEndInTheSweepIsBattedAndTheFlipperReachesItsStop(GizmoKind kind) {
        Board board = flipperWithBall(kind, 8.7424038765061050, 8.1631759111665350);
        board.keyDown(90);
        FlipperView flipper = (FlipperView) board.gizmo("F").orElseThrow();
        for (int tick = 1; tick <= 5; tick++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", tick).isEmpty();
        }
        assertThat(flipper.angleFromRest()).isEqualTo(90.0);
        double speed = board.ball("B").orElseThrow().velocity().length();
        assertThat(speed).isBetween(OMEGA * 0.5, (1 + 0.95) * OMEGA * 1.5);
        assertThat(board.guardsFired()).isEqualTo(GuardCounts.NONE);
    }

    /**
     * x(t) = 19 + 0.6 t reaches 19.75 (touching the right wall) at t = 1.25 s, tick 75. Gravity is parallel to the
     * wall, so nothing presses the ball into it: coefficient 1.0 returns it at exactly -0.6 L/s.
     */
    @Test
    void aSlowBallMeetingAVerticalWallComesBack() {
        Board board = new Board();
        board.setFriction(0, 0);
        board.addBall("B", 19.0, 10.0, 0.6, -15);
        for (int tick = 1; tick <= 120; tick++) {
            board.tick(DT);
        }
        BallView ball = board.ball("B").orElseThrow();
        assertThat(ball.velocity().x()).isCloseTo(-0.6, within(1e-12));
        // back from the wall for 45 of the 120 ticks (less the part of tick 75 before the bounce)
        assertThat(ball.position().x()).isCloseTo(19.75 - 0.6 * 45 * DT, within(0.6 * DT));
    }

    /**
     * Friction 0: nothing acts along the floor, so |vx| = 2 for ever; floor bounces and the energy correction may
     * change only the vertical velocity. 200,000 ticks, over 3,000 bounces.
     */
    @Test
    void aBallBouncingAlongTheFloorKeepsItsHorizontalSpeed() {
        Board board = new Board();
        board.setFriction(0, 0);
        board.addBall("B", 1.0, 10.0, 2.0, 0);
        for (int tick = 1; tick <= 200_000; tick++) {
            board.tick(DT);
            assertThat(Math.abs(board.ball("B").orElseThrow().velocity().x())).as("tick %d", tick)
                    .isCloseTo(2.0, within(1e-9));
        }
    }
}
