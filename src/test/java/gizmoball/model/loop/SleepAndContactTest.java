package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.Board;
import gizmoball.model.Invariants;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import physics.Vect;

/**
 * Persistent contact and sleeping (docs/design.md, "Resting and rolling contact", "Sleeping"): balls at rest cost
 * nothing and stay exactly put, and wake whenever something can reach them or the board changes under them.
 */
class SleepAndContactTest {
    private static final double DT = 1.0 / 60;
    private static final double R = Board.BALL_RADIUS;

    private static void run(Board board, int ticks) {
        for (int i = 0; i < ticks; i++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", i).isEmpty();
        }
    }

    private static BallView ball(Board board, String name) {
        return board.ball(name).orElseThrow();
    }

    /** Long enough for a ball lying still to fall asleep. */
    private static final int SETTLE = (int) Math.round(LoopSettings.STANDARD.sleepTime() / DT) + 5;

    /**
     * Sleep is counted in seconds, so a board run at another dt keeps its meaning: a ball set on the floor comes to
     * rest on it in its first tick (it has no contact before), and falls asleep in the tick that brings its time
     * still on the floor to {@link LoopSettings#sleepTime()}, not after a number of ticks.
     */
    @ParameterizedTest
    @CsvSource({"60", "120", "240", "25", "7"})
    void aBallFallsAsleepAfterTheSleepTimeAtAnyTickRate(int ticksPerSecond) {
        double dt = 1.0 / ticksPerSecond;
        long ticksToSleep = (long) Math.ceil(LoopSettings.STANDARD.sleepTime() * ticksPerSecond - 1e-9);
        Board board = new Board();
        board.addBall("B", 10, Board.SIZE - R, 0, 0);
        board.tick(dt);
        for (int t = 1; t < ticksToSleep; t++) {
            board.tick(dt);
            assertThat(ball(board, "B").isAsleep()).as("tick %d of %d", t, ticksToSleep).isFalse();
        }
        board.tick(dt);
        assertThat(ball(board, "B").isAsleep()).isTrue();
    }

    @Test
    void aBallLyingOnTheFloorFallsAsleepAndCostsNoCollision() {
        Board board = new Board();
        board.addBall("B", 10, Board.SIZE - R, 0, 0);
        run(board, SETTLE);
        assertThat(ball(board, "B").isAsleep()).isTrue();
        board.tick(DT);
        assertThat(board.lastTick().collisions()).isZero();
        assertThat(board.lastTick().ballsAwake()).isZero();
        assertThat(board.lastTick().ballsAsleep()).isEqualTo(1);
        assertThat(ball(board, "B").position()).isEqualTo(new Vect(10, Board.SIZE - R));
    }

    /** B rolls along the floor at 5 L/s, reaches the sleeping A after 1.5 s and, equal masses head on, they swap. */
    @Test
    void aBallRollingIntoASleepingOneWakesItAndTheySwapVelocities() {
        Board board = new Board();
        board.setFriction(0, 0);
        board.addBall("A", 10, Board.SIZE - R, 0, 0);
        board.addBall("B", 2, Board.SIZE - R, 5, 0);
        run(board, SETTLE);
        assertThat(ball(board, "A").isAsleep()).isTrue();
        run(board, 120 - SETTLE);   // contact at (10 - 2 - 2R) / 5 = 1.5 s, tick 90
        assertThat(ball(board, "A").isAsleep()).isFalse();
        assertThat(ball(board, "A").velocity().x()).isCloseTo(5, within(1e-9));
        assertThat(ball(board, "B").velocity().x()).isCloseTo(0, within(1e-9));
    }

    @Test
    void aBallAsleepOnAFlipperIsBattedWhenTheFlipperSwings() {
        Board board = new Board();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 8, 10);
        board.rotate("F");   // lies along the top of its box: the bar's top is the line y = 10
        board.addBall("B", 9, 10 - R, 0, 0);
        board.bindKey(32, KeyEdge.DOWN, "F");
        run(board, SETTLE);
        assertThat(ball(board, "B").isAsleep()).isTrue();
        board.keyDown(32);
        run(board, 10);
        BallView ball = ball(board, "B");
        assertThat(ball.isAsleep()).isFalse();
        // batted: far faster than anything resting contact leaves (two ticks of gravity)
        assertThat(ball.velocity().length()).isGreaterThan(2 * board.gravity() * DT);
    }

    @Test
    void deletingWhatABallSleepsOnLetsItFall() {
        Board board = new Board();
        board.setFriction(0, 0);
        board.addGizmo(GizmoKind.SQUARE, "S", 5, 10);
        board.addBall("B", 5.5, 10 - R, 0, 0);
        run(board, SETTLE);
        assertThat(ball(board, "B").isAsleep()).isTrue();
        board.delete("S");
        run(board, 10);
        // free fall from rest for 10 ticks of semi-implicit Euler: y += g dt^2 (1 + 2 + ... + 10)
        assertThat(ball(board, "B").position().y()).isCloseTo(10 - R + board.gravity() * DT * DT * 55, within(1e-9));
    }

    @Test
    void reversedGravityWakesASleepingBall() {
        Board board = new Board();
        board.setFriction(0, 0);
        board.addBall("B", 10, Board.SIZE - R, 0, 0);
        run(board, SETTLE);
        assertThat(ball(board, "B").isAsleep()).isTrue();
        board.setGravity(-25);
        run(board, 10);
        assertThat(ball(board, "B").position().y()).isCloseTo(Board.SIZE - R - 25 * DT * DT * 55, within(1e-9));
    }

    /** Gravity upward: a ball sleeps against the ceiling in the absorber's launch column; the fired ball meets it. */
    @Test
    void aBallFiredFromAnAbsorberWakesTheSleeperItMeets() {
        Board board = new Board();
        board.setGravity(-25);
        board.addAbsorber("A", 0, 19, 20, 20);
        board.addBall("H", 10, 19.5, 0, 0);   // captured
        board.addBall("S", 19.75, R, 0, 0);   // against the ceiling, in the column the launch goes up
        board.bindKey(32, KeyEdge.DOWN, "A");
        run(board, SETTLE);
        assertThat(ball(board, "S").isAsleep()).isTrue();
        board.keyDown(32);
        boolean woke = false;
        for (int i = 0; i < 60 && !woke; i++) {
            board.tick(DT);
            woke = !ball(board, "S").isAsleep();
        }
        assertThat(woke).isTrue();
    }

    /**
     * Three rows of touching balls between two square walls on the floor: 8, then 7 in the grooves (0.5 sin 60
     * degrees higher), then 6. Once asleep the pile stays exactly where it is.
     */
    @Test
    void aSleepingPileNeitherCreepsNorSinksForAHundredThousandTicks() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SQUARE, "L", 4, 19);
        board.addGizmo(GizmoKind.SQUARE, "R", 9, 19);
        double rise = 2 * R * Math.sin(Math.toRadians(60));
        int n = 0;
        for (int row = 0; row < 3; row++) {
            for (int i = 0; i < 8 - row; i++) {
                board.addBall("P" + n++, 5 + R + row * R + i * 2 * R, Board.SIZE - R - row * rise, 0, 0);
            }
        }
        run(board, 300);
        List<Vect> settled = new ArrayList<>();
        for (BallView ball : board.balls()) {
            assertThat(ball.isAsleep()).as(ball.name()).isTrue();
            settled.add(ball.position());
        }
        for (int i = 0; i < 100_000; i++) {
            board.tick(DT);
        }
        assertThat(Invariants.violations(board)).isEmpty();
        List<Vect> after = board.balls().stream().map(BallView::position).toList();
        assertThat(after).isEqualTo(settled);
    }

    /**
     * Without friction nothing acts along a level floor, so a ball rolling over seams keeps its speed exactly, however
     * slowly it rolls and wherever it starts, on a seam too: the corner at a seam is flush with the faces and holds
     * nothing back (a corner kept as a contact of its own would tilt its normal backwards once the ball is past it).
     */
    @ParameterizedTest(name = "{0} L/s from x = {1}")
    @CsvSource({"0.2, 6.5", "0.5, 6.5", "1, 6.5", "1, 7", "1, 6.99", "2, 7", "3, 6.25"})
    void aSlowBallRollingOverSeamsKeepsItsSpeed(double speed, double x) {
        Board board = new Board();
        board.setFriction(0, 0);
        for (int cell = 0; cell < Board.SIZE; cell++) {
            board.addGizmo(GizmoKind.SQUARE, "S" + cell, cell, 18);
        }
        board.addBall("B", x, 18 - R, speed, 0);
        int ticks = (int) Math.ceil(5 / (speed * DT));   // five seams' worth of rolling, short of the right wall
        for (int t = 0; t < ticks; t++) {
            board.tick(DT);
            BallView ball = ball(board, "B");
            assertThat(ball.velocity().x()).as("tick %d at x = %s", t, ball.position().x()).isEqualTo(speed);
            assertThat(ball.position().y()).as("tick %d", t).isEqualTo(18 - R);
        }
    }

    /** After the first tick's landing, rolling over the nine seams of ten squares takes no collision at all. */
    @Test
    void aBallRollingAcrossTenSeamsHasNoCollision() {
        Board board = new Board();
        board.setFriction(0, 0);
        for (int x = 3; x < 13; x++) {
            board.addGizmo(GizmoKind.SQUARE, "S" + x, x, 10);
        }
        board.addBall("B", 3.5, 10 - R, 6, 0);
        board.tick(DT);
        while (ball(board, "B").position().x() < 12.5) {
            board.tick(DT);
            assertThat(board.lastTick().collisions()).as("at x = %s", ball(board, "B").position().x()).isZero();
            assertThat(ball(board, "B").position().y()).isEqualTo(10 - R);
        }
    }

    /**
     * Ten triangles make one 45-degree slope, the line x + y = 18. A ball let go on it slides down with no collision
     * after its landing, at a speed growing by g dt sin 45 degrees each tick, staying on the line.
     */
    @Test
    void aBallSlidingDownASlopeOfTrianglesHasNoCollision() {
        Board board = new Board();
        board.setFriction(0, 0);
        for (int k = 0; k < 10; k++) {
            board.addGizmo(GizmoKind.TRIANGLE, "T" + k, 2 + k, 15 - k);
            board.rotate("T" + k);
            board.rotate("T" + k);   // hypotenuse from (2 + k, 16 - k) to (3 + k, 15 - k), solid below it
        }
        double off = R / Math.sqrt(2);
        board.addBall("B", 11.5 - off, 6.5 - off, 0, 0);
        board.tick(DT);
        double g = board.gravity();
        for (int tick = 2; ball(board, "B").position().x() > 3; tick++) {
            board.tick(DT);
            BallView ball = ball(board, "B");
            assertThat(board.lastTick().collisions()).as("tick %d", tick).isZero();
            double distance = (ball.position().x() + ball.position().y() - 18) / -Math.sqrt(2);
            assertThat(distance).as("tick %d", tick).isCloseTo(R, within(1e-9));
            assertThat(ball.velocity().length()).as("tick %d", tick).isCloseTo(tick * g * DT / Math.sqrt(2),
                    within(1e-9));
        }
    }

    /**
     * The loop keeps the awake balls, and how many sleep, from tick to tick while nothing changes them
     * ({@code StepContext.findAwake}): after a ball is added, deleted or moved between ticks (the last one deleted
     * too, which wakes nothing), and as balls fall asleep, each report counts what the balls themselves say, and a ball
     * added moves in its first tick.
     */
    @Test
    void theBallsAwakeAndAsleepAreCountedAfreshWhenTheyChangeBetweenTicks() {
        Board board = new Board();
        board.addBall("A", 5, Board.SIZE - R, 0, 0);
        board.addBall("B", 10, Board.SIZE - R, 0, 0);
        countsMatch(board, SETTLE);
        assertThat(board.lastTick().ballsAsleep()).isEqualTo(2);

        board.addBall("C", 15, 5, 0, 0);   // it falls, and bounces on the elastic floor
        countsMatch(board, 1);
        assertThat(ball(board, "C").position().y()).isGreaterThan(5);
        countsMatch(board, 2 * SETTLE);

        board.delete("C");
        countsMatch(board, 2 * SETTLE);
        assertThat(board.lastTick().ballsAsleep()).isEqualTo(2);

        board.moveBall("B", 10, 10);   // off the floor: it wakes and falls
        countsMatch(board, 1);
        assertThat(ball(board, "B").position().y()).isGreaterThan(10);
        assertThat(board.lastTick().ballsAwake()).isPositive();
        countsMatch(board, 2 * SETTLE);

        board.delete("A");
        countsMatch(board, 1);
        board.delete("B");   // the last: no ball is left to wake, so only the board's list of balls says it went
        countsMatch(board, 1);
        assertThat(board.lastTick().ballsAwake()).isZero();
    }

    /** Ticks the board, each report's balls awake and asleep those the balls' own states give. */
    private static void countsMatch(Board board, int ticks) {
        for (int i = 0; i < ticks; i++) {
            board.tick(DT);
            long asleep = board.balls().stream().filter(b -> !b.isCaptured() && b.isAsleep()).count();
            long awake = board.balls().stream().filter(b -> !b.isCaptured() && !b.isAsleep()).count();
            assertThat(board.lastTick().ballsAsleep()).as("asleep, tick %d", i).isEqualTo(asleep);
            assertThat(board.lastTick().ballsAwake()).as("awake, tick %d", i).isEqualTo(awake);
        }
    }
}
