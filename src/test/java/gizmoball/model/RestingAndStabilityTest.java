package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.LoopMode;

import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import physics.Vect;

/** Items 11-14 of PHYSICS-PITFALLS.md: resting contact, wedges, seams, fast balls; plus touching balls. */
class RestingAndStabilityTest {
    private static final double DT = Board.DEFAULT_TICK;
    private static final double R = Board.BALL_RADIUS;

    private static void assertStaysAtRest(Board board, Vect where, int ticks) {
        for (int i = 0; i < ticks; i++) {
            board.tick(DT);
            BallView ball = board.ball("B").orElseThrow();
            assertThat(ball.position().x()).as("x, tick %d", i).isCloseTo(where.x(), within(1e-9));
            assertThat(ball.position().y()).as("y, tick %d", i).isCloseTo(where.y(), within(1e-9));
            assertThat(ball.velocity().length()).as("speed, tick %d", i).isLessThan(1e-9);
        }
        assertThat(Invariants.violations(board)).isEmpty();
    }

    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void aBallLyingOnTheFloorStaysThereForTenThousandTicks(LoopMode mode) {
        Board board = new Board();
        board.setLoopMode(mode);
        board.addBall("B", 10, Board.SIZE - R, 0, 0);
        assertStaysAtRest(board, new Vect(10, Board.SIZE - R), 10_000);
    }

    @Test
    void aBallLyingOnASquareStaysThere() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SQUARE, "S", 5, 10);
        board.addBall("B", 5.5, 10 - R, 0, 0);
        assertStaysAtRest(board, new Vect(5.5, 10 - R), 10_000);
    }

    @Test
    void aBallDroppedOnALossyFlatFlipperComesToRestOnItAndStays() {
        Board board = new Board();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 8, 10);
        board.rotate("F");   // lies along the top of its box: the bar's top is the line y = 10
        board.addBall("B", 9, 9, 0, 0);
        for (int i = 0; i < 600; i++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", i).isEmpty();
        }
        // coefficient 0.95: each bounce keeps 0.95 of the speed, from about 3.5 L/s to below 2 g dt within 600 ticks
        assertStaysAtRest(board, new Vect(9, 10 - R), 2_000);
    }

    @Test
    void aBallRestingInAVeeStaysAndTheLoopDoesNotFreeze() {
        Board board = new Board();
        board.addGizmo(GizmoKind.TRIANGLE, "L", 8, 10);
        board.addGizmo(GizmoKind.TRIANGLE, "R", 9, 10);
        for (int i = 0; i < 3; i++) {
            board.rotate("L");   // right angle bottom-left: slope from (8, 10) down to (9, 11)
        }
        board.rotate("R");
        board.rotate("R");       // right angle bottom-right: slope from (9, 11) up to (10, 10)
        Vect rest = new Vect(9, 11 - R * Math.sqrt(2));   // touching both 45-degree slopes
        board.addBall("B", rest.x(), rest.y(), 0, 0);
        assertStaysAtRest(board, rest, 10_000);
    }

    @Test
    void aBallSlidingIntoANarrowWedgeNeitherFreezesTheLoopNorSinks() {
        Board board = new Board();
        board.addGizmo(GizmoKind.TRIANGLE, "T", 9, 19);
        for (int i = 0; i < 3; i++) {
            board.rotate("T");   // slope from (9, 19) down to (10, 20)
        }
        board.addGizmo(GizmoKind.SQUARE, "S", 10, 19);   // its left face x = 10 closes a 45-degree wedge
        board.addBall("B", 9.3, 18.9, 0, 0);
        for (int i = 0; i < 10_000; i++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", i).isEmpty();
        }
        BallView ball = board.ball("B").orElseThrow();
        assertThat(ball.position().x()).isBetween(9.0, 10 - R + 1e-9);
    }

    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void aBallRollingAcrossARowOfSquaresDoesNotSnagOnTheSeams(LoopMode mode) {
        Board board = new Board();
        board.setLoopMode(mode);
        board.setFriction(0, 0);
        for (int x = 3; x < 13; x++) {
            board.addGizmo(GizmoKind.SQUARE, "S" + x, x, 10);
        }
        board.addBall("B", 3.5, 10 - R, 6, 0);
        int ticks = 0;
        while (board.ball("B").orElseThrow().position().x() < 12.5) {
            board.tick(DT);
            ticks++;
            BallView ball = board.ball("B").orElseThrow();
            assertThat(ball.position().y()).as("tick %d", ticks).isCloseTo(10 - R, within(1e-9));
            assertThat(ball.velocity().x()).as("tick %d", ticks).isCloseTo(6, within(1e-9));
            assertThat(ball.velocity().y()).as("tick %d", ticks).isCloseTo(0, within(1e-9));
        }
        assertThat(board.ball("B").orElseThrow().position().x()).isCloseTo(3.5 + 6 * ticks * DT, within(1e-9));
    }

    @Test
    void aBallAt200LPerSecondNeverPassesAOneCellWall() {
        Random random = new Random(14);
        for (int run = 0; run < 40; run++) {
            Board board = new Board();
            for (int x = 0; x < Board.SIZE; x++) {
                board.addGizmo(x % 2 == 0 ? GizmoKind.SQUARE : GizmoKind.TRIANGLE, "W" + x, x, 10);
            }
            double angle = Math.PI * (0.05 + 0.9 * random.nextDouble());
            double x0 = 1 + 18 * random.nextDouble();
            board.addBall("B", x0, 15, 200 * Math.cos(angle), -200 * Math.sin(angle));
            for (int i = 0; i < 120; i++) {
                board.tick(DT);
                BallView ball = board.ball("B").orElseThrow();
                assertThat(ball.position().y()).as("seed 14 run %d tick %d", run, i).isGreaterThan(10);
                assertThat(Invariants.violations(board)).as("seed 14 run %d tick %d", run, i).isEmpty();
            }
        }
    }

    @Test
    void fastBallsAtThinCornersNeverEndUpInside() {
        Random random = new Random(1414);
        for (int run = 0; run < 60; run++) {
            Board board = new Board();
            board.setGravity(0);
            board.addGizmo(GizmoKind.TRIANGLE, "T", 9, 9);
            board.rotate("T");
            board.addGizmo(GizmoKind.TRIANGLE, "U", 10, 10);
            board.addGizmo(GizmoKind.CIRCLE, "C", 9, 10);
            board.addGizmo(GizmoKind.SQUARE, "S", 10, 9);
            double angle = 2 * Math.PI * random.nextDouble();
            board.addBall("B", 10 + 6 * Math.cos(angle), 10 + 6 * Math.sin(angle),
                    -200 * Math.cos(angle + 0.1 * random.nextGaussian()), -200 * Math.sin(angle + 0.1 * random.nextGaussian()));
            for (int i = 0; i < 100; i++) {
                board.tick(DT);
                assertThat(Invariants.violations(board)).as("seed 1414 run %d tick %d", run, i).isEmpty();
            }
        }
    }

    @Test
    void ballsTouchingAtLoadSideBySideOrStackedStayExactlyWhereTheyAre() {
        Board board = new Board();
        board.addBall("B", 10, Board.SIZE - R, 0, 0);
        board.addBall("C", 10 + 2 * R, Board.SIZE - R, 0, 0);
        board.addBall("D", 4, Board.SIZE - R, 0, 0);
        board.addBall("E", 4, Board.SIZE - 3 * R, 0, 0);   // on top of D
        for (int i = 0; i < 5_000; i++) {
            board.tick(DT);
        }
        assertThat(Invariants.violations(board)).isEmpty();
        assertThat(board.ball("B").orElseThrow().position()).isEqualTo(new Vect(10, Board.SIZE - R));
        assertThat(board.ball("C").orElseThrow().position()).isEqualTo(new Vect(10 + 2 * R, Board.SIZE - R));
        assertThat(board.ball("D").orElseThrow().position()).isEqualTo(new Vect(4, Board.SIZE - R));
        assertThat(board.ball("E").orElseThrow().position()).isEqualTo(new Vect(4, Board.SIZE - 3 * R));
        board.balls().forEach(ball -> assertThat(ball.velocity().length()).isLessThan(1e-9));
    }

    @Test
    void ballsTouchingAtLoadAndMovingStayApartAndFinite() {
        Board board = new Board();
        board.addBall("B", 10, Board.SIZE - R, 3, 0);
        board.addBall("C", 10 + 2 * R, Board.SIZE - R, 0, 0);
        board.addBall("D", 4, 5, 0, 0);
        board.addBall("E", 4, 5 + 2 * R, 0, 0);   // touching, one above the other, falling together
        board.addBall("F", 12, 5, 10, -3);
        board.addBall("G", 12 + 2 * R, 5, -10, 3);   // touching and closing at load
        for (int i = 0; i < 5_000; i++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", i).isEmpty();
        }
    }

    @Test
    void aBallIntoTheBoardCornerMeetsBothWallsInOneTick() {
        Board board = new Board();
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addBall("B", 1, 1, -30, -30);   // reaches (0.25, 0.25), touching both walls at once, at t = 0.025
        board.tick(0.03);
        BallView ball = board.ball("B").orElseThrow();
        assertThat(ball.velocity().x()).isCloseTo(30, within(1e-9));
        assertThat(ball.velocity().y()).isCloseTo(30, within(1e-9));
        assertThat(ball.position().x()).isCloseTo(R + 30 * 0.005, within(1e-9));
        assertThat(ball.position().y()).isCloseTo(R + 30 * 0.005, within(1e-9));
    }

    @Test
    void ballBallCollisionsConserveMomentumAndEnergy() {
        Board board = new Board();
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addBall("B", 5, 10, 8, 1);
        board.addBall("C", 9, 10.2, -6, 0.5);
        Vect momentum = new Vect(2, 1.5);
        double energy = (64 + 1 + 36 + 0.25) / 2;
        for (int i = 0; i < 30; i++) {   // they meet within 0.3 s; no wall is reached
            board.tick(DT);
        }
        Vect b = board.ball("B").orElseThrow().velocity();
        Vect c = board.ball("C").orElseThrow().velocity();
        assertThat(b.x()).as("they have collided").isLessThan(8);
        assertThat(b.plus(c).minus(momentum).length()).isLessThan(1e-9);
        assertThat((b.dot(b) + c.dot(c)) / 2).isCloseTo(energy, within(1e-9));
    }

    @Test
    void equalBallsMeetingHeadOnSwapVelocities() {
        Board board = new Board();
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addBall("B", 5, 10, 10, 0);
        board.addBall("C", 9, 10, -4, 0);
        for (int i = 0; i < 30; i++) {
            board.tick(DT);
        }
        assertThat(board.ball("B").orElseThrow().velocity().x()).isCloseTo(-4, within(1e-9));
        assertThat(board.ball("C").orElseThrow().velocity().x()).isCloseTo(10, within(1e-9));
    }
}
