package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.LoopMode;

import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import physics.Vect;

/** Balls against flippers at rest and swinging: batting, coefficient 0.95, pinching, never inside. */
class FlipperCollisionTest {
    private static final double DT = Board.DEFAULT_TICK;
    private static final double R = Board.BALL_RADIUS;
    /** A flipper's coefficient of reflection, from the product description's table of gizmos (docs/rules.md). */
    private static final double FLIPPER_REFLECTION = 0.95;

    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void aSwingingFlipperBatsARestingBallUpward(LoopMode mode) {
        Board board = new Board();
        board.setLoopMode(mode);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 5, 10);   // pivot (5.25, 10.25), tip swings on radius 1.5
        board.addGizmo(GizmoKind.SQUARE, "S", 6, 12);
        board.addBall("B", 6.5, 12 - R, 0, 0);                 // on the square, 1.95 L from the pivot: in reach
        board.tick(DT);
        board.bindKey(32, KeyEdge.DOWN, "F");
        board.keyDown(32);
        FlipperView flipper = (FlipperView) board.gizmo("F").orElseThrow();
        double fastestUp = 0;
        for (int i = 0; i < 20; i++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", i).isEmpty();
            fastestUp = Math.max(fastestUp, -board.ball("B").orElseThrow().velocity().y());
        }
        // The contact is found with a gap of up to 1e-10 L (physics-lib's contact search): that moves the
        // ball's speed by well under 1e-6 L/s.
        assertThat(fastestUp).isBetween(upwardSpeedAfterTheBat() - board.gravity() * DT - 1e-6,
                upwardSpeedAfterTheBat() + 1e-6);
        assertThat(flipper.angleFromRest()).isEqualTo(90.0);
        assertThat(flipper.lastTriggeredAt()).isFinite();
    }

    /**
     * The ball (centre B, 1.95 L from the pivot P) is beyond the bar's reach, so the tip's round end (centre C,
     * 1.5 L from P, radius 0.25) bats it, when |CB| = 0.5. At the contact point K the flipper's surface moves at
     * w x PK (w = 1080 deg/s); the ball, at rest, leaves along the normal n = CB/|CB| at (1 + 0.95)(v_K . n).
     * That normal points down into the square, which returns the downward part unchanged (coefficient 1): the
     * ball goes up at that speed. Gravity may act on it for up to one tick before the tick ends.
     */
    private static double upwardSpeedAfterTheBat() {
        double w = Math.toRadians(1080);
        double toBall = Math.hypot(6.5 - 5.25, 11.75 - 10.25);
        double cap = 1.5;
        double reach = 2 * R;
        // In the bar's frame (P at 0, the bar along +x, turning towards +y): C = (cap, 0), B at angle phi.
        double phi = Math.acos((cap * cap + toBall * toBall - reach * reach) / (2 * cap * toBall));
        double nx = (toBall * Math.cos(phi) - cap) / reach;
        double ny = toBall * Math.sin(phi) / reach;
        double kx = cap + R * nx;
        double ky = R * ny;
        double speed = (1 + FLIPPER_REFLECTION) * w * (-ky * nx + kx * ny);
        // On the board the bar points from straight down (0, 1) turned by a towards +x; "turning" is (cos a, -sin a).
        double a = Math.atan2(6.5 - 5.25, 11.75 - 10.25) - phi;
        double downward = nx * Math.cos(a) - ny * Math.sin(a);
        return speed * downward;
    }

    @Test
    void aFlipperAtRestReflectsWithCoefficientPoint95() {
        Board board = new Board();
        board.setFriction(0, 0);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 8, 10);
        board.rotate("F");   // lies along the top edge: the bar's top is y = 10
        board.addBall("B", 9, 8, 0, 0);
        double before = 0;
        for (int i = 0; i < 60; i++) {
            double vy = board.ball("B").orElseThrow().velocity().y();
            board.tick(DT);
            double after = board.ball("B").orElseThrow().velocity().y();
            if (after < 0) {
                before = vy;
                break;
            }
        }
        // the bounce tick: gravity first (v + g dt), then the bounce keeps 0.95 of it, reversed
        BallView ball = board.ball("B").orElseThrow();
        assertThat(ball.velocity().y()).isCloseTo(-0.95 * (before + board.gravity() * DT), within(1e-9));
        assertThat(ball.velocity().x()).isCloseTo(0, within(1e-12));
    }

    @Test
    void aBallPinchedBetweenARisingFlipperAndASquareStopsTheFlipperInsteadOfEnteringIt() {
        Board board = new Board();
        board.setGravity(0);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 5, 10);
        board.addGizmo(GizmoKind.SQUARE, "S", 6, 9);       // right above the flipper's top edge
        board.addGizmo(GizmoKind.SQUARE, "T", 7, 9);
        board.addBall("B", 6.9, 10.6, 0, 0);               // in the sweep, under the squares
        board.trigger("F");
        for (int i = 0; i < 600; i++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", i).isEmpty();
        }
    }

    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void aBallPinchedBetweenARisingFlipperAndTheOuterWallStaysOutOfBoth(LoopMode mode) {
        Board board = new Board();
        board.setLoopMode(mode);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 0, 0);   // swings up to lie against the top wall
        board.addBall("B", 1.2, 0.6, 0, -1);
        board.trigger("F");
        FlipperView flipper = (FlipperView) board.gizmo("F").orElseThrow();
        for (int i = 0; i < 600; i++) {
            if (i % 60 == 59) {
                board.trigger("F");
            }
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", i).isEmpty();
            assertThat(flipper.angleFromRest()).isBetween(0.0, 90.0);
        }
    }

    /** Random balls thrown at flippers that are toggled at random: nothing ever ends up inside anything. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void swingingFlippersNeverLetABallInside(LoopMode mode) {
        long seed = 90210;
        Random random = new Random(seed);
        for (int run = 0; run < 12; run++) {
            Board board = new Board();
            board.setLoopMode(mode);
            board.addGizmo(GizmoKind.LEFT_FLIPPER, "L", 6, 14);
            board.addGizmo(GizmoKind.RIGHT_FLIPPER, "R", 10, 14);
            board.addGizmo(GizmoKind.LEFT_FLIPPER, "M", 2, 6);
            for (int k = 0; k < random.nextInt(3); k++) {
                board.rotate("M");
            }
            board.addGizmo(GizmoKind.SQUARE, "S", 8, 13);
            for (int b = 0; b < 4; b++) {
                double x = 1 + 18 * random.nextDouble();
                double y = 1 + 12 * random.nextDouble();
                try {
                    board.addBall("B" + b, x, y, 40 * random.nextGaussian(), 40 * random.nextGaussian());
                } catch (BoardEditException overlapping) {
                    // a random spot on a gizmo or ball: that ball is simply not added
                }
            }
            for (int i = 0; i < 400; i++) {
                if (random.nextInt(6) == 0) {
                    board.trigger(new String[] {"L", "R", "M"}[random.nextInt(3)]);
                }
                board.tick(DT);
                assertThat(Invariants.violations(board)).as("seed %d run %d tick %d", seed, run, i).isEmpty();
            }
        }
    }

    @Test
    void aBallFallingOnAFlipperEndIsResolvedAtTheRoundEnd() {
        Board board = new Board();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 5, 10);
        board.rotate("F");   // bar along the top edge from the pivot (6.75, 10.25) to the tip (5.25, 10.25)
        board.addBall("B", 5.25 - 0.3, 8, 0, 0);   // falls past the tip's round end, off its centre
        board.trigger("F");
        for (int i = 0; i < 120; i++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", i).isEmpty();
        }
        BallView ball = board.ball("B").orElseThrow();
        assertThat(ball.position().minus(new Vect(5.25, 10.25)).length()).isGreaterThan(0.5 - 1e-9);
    }
}
