package gizmoball.model;

import gizmoball.model.gizmo.Setting;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.model.gizmo.SpinnerView;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.LoopMode;

import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import physics.Vect;

/**
 * The spinner (issue 22): a 2x2 bar turning without end about the centre of its box. Its angle after any number of
 * ticks, the speed of a ball its end bats, a ball jammed in a pocket stalling it, its actions, and no ball ever inside.
 */
class SpinnerTest {
    private static final double DT = Board.DEFAULT_TICK;
    private static final double R = Board.BALL_RADIUS;
    /** The spinner's coefficient of reflection: a flipper's, from the product description's table (docs/rules.md). */
    private static final double REFLECTION = 0.95;
    /** From the pivot to the centre of each round end: the bar is 2 L long and its ends have radius 0.25. */
    private static final double ARM = 0.75;
    private static final double END_RADIUS = 0.25;
    private static final int KEY = 65;

    private static SpinnerView spinner(Board board, String name) {
        return (SpinnerView) board.gizmo(name).orElseThrow();
    }

    /** The angle n ticks of one turn a second reach: 2 pi n dt, reduced to [0, 2 pi). */
    private static double turned(int ticks, double turnsPerSecond) {
        double angle = 2 * Math.PI * turnsPerSecond * ticks * DT;
        return angle - 2 * Math.PI * Math.floor(angle / (2 * Math.PI));
    }

    @Test
    void itTurnsOneTurnASecondClockwiseFromLyingFlatAndItsEndsStayInItsBox() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SPINNER, "SN", 8, 8);
        SpinnerView s = spinner(board, "SN");
        assertThat(s.angle()).isZero();
        assertThat(s.ends()).containsExactly(new Vect(9 - ARM, 9), new Vect(9 + ARM, 9));
        for (int tick = 1; tick <= 150; tick++) {
            board.tick(DT);
            // Each tick adds 2 pi / 60 in rounding-sized steps; 150 of them stay within 1e-12 of the closed form.
            assertThat(s.angle()).as("tick %d", tick).isCloseTo(turned(tick, 1), within(1e-12));
            assertThat(s.angle()).isBetween(0.0, 2 * Math.PI);
            for (Vect end : s.ends()) {
                assertThat(end.minus(s.pivot()).length()).isCloseTo(ARM, within(1e-12));
                assertThat(end.x() - END_RADIUS).isGreaterThanOrEqualTo(8 - 1e-12);
                assertThat(end.x() + END_RADIUS).isLessThanOrEqualTo(10 + 1e-12);
                assertThat(end.y() - END_RADIUS).isGreaterThanOrEqualTo(8 - 1e-12);
                assertThat(end.y() + END_RADIUS).isLessThanOrEqualTo(10 + 1e-12);
            }
        }
        // A quarter second in, the bar is upright: clockwise on the screen is +x toward +y.
        board.setSpinnerState("SN", 0, true);
        for (int tick = 0; tick < 15; tick++) {
            board.tick(DT);
        }
        assertThat(s.ends().get(1).x()).isCloseTo(9, within(1e-12));
        assertThat(s.ends().get(1).y()).isCloseTo(9 + ARM, within(1e-12));
    }

    /**
     * A still ball, no gravity or friction, 1.1 L from the pivot and 60 degrees ahead of the bar, is met by the end's
     * round cap (centre C at a = 0.75 from the pivot P) when |CB| = 2r = 0.5: in the bar's frame, with the ball at
     * angle phi from the bar, cos phi = (a^2 + b^2 - 0.25) / (2ab). The normal is n = (B - C) / 0.5 and the contact
     * point K = C + 0.25 n moves at w x PK. The ball, at rest, has relative velocity -v_K; reflected with
     * coefficient e its normal part becomes (1 + e)(v_K . n), and it leaves along n at that speed:
     * (1 + e) w (K x n) = (1 + e) w a n_y, since K x n = C x n.
     */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void aStillBallTheEndTouchesLeavesAtTheClosedFormSpeed(LoopMode mode) {
        Board board = new Board();
        board.setLoopMode(mode);
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addGizmo(GizmoKind.SPINNER, "SN", 8, 8);
        double b = 1.1;
        double ahead = Math.toRadians(60);
        board.addBall("B", 9 + b * Math.cos(ahead), 9 + b * Math.sin(ahead), 0, 0);
        double a = ARM;
        double phi = Math.acos((a * a + b * b - 4 * R * R) / (2 * a * b));
        double ny = b * Math.sin(phi) / (2 * R);
        double expected = (1 + REFLECTION) * 2 * Math.PI * a * ny;
        // The end reaches it after turning by 60 degrees less phi: within the first 9 ticks.
        BallView ball = board.ball("B").orElseThrow();
        for (int i = 0; i < 20; i++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", i).isEmpty();
        }
        // physics-lib finds the contact within a gap of 1e-10 L, which moves the speed by well under 1e-6 L/s.
        assertThat(ball.velocity().length()).isCloseTo(expected, within(1e-6));
        // It left along the normal at the contact: (cos, sin) of the bar's angle then plus the normal's angle.
        double barThen = ahead - phi;
        double nx = (b * Math.cos(phi) - a) / (2 * R);
        Vect along = new Vect(nx * Math.cos(barThen) - ny * Math.sin(barThen), nx * Math.sin(barThen) + ny * Math.cos(barThen));
        assertThat(ball.velocity().unitSize().minus(along).length()).isLessThan(1e-6);
    }

    /**
     * A ball still in the top-left corner, its centre at (0.25, 0.25), under a spinner in the corner cells: the end's
     * cap can push it only further into the corner, so the spinner stalls where the cap first touches it. The ball
     * is at b = |(-0.75, -0.75)| from the pivot (1, 1), in direction 225 degrees; the cap touches it when the end
     * at 0.75 from the pivot points within delta of that, cos delta = (a^2 + b^2 - 0.25) / (2ab). The end that
     * gets there first is the one starting at 180 degrees: the bar then lies at 225 - delta - 180 degrees.
     */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void aBallInACornerPocketStallsItUntilTheBallHasGone(LoopMode mode) {
        Board board = new Board();
        board.setLoopMode(mode);
        board.setGravity(0);
        board.addGizmo(GizmoKind.SPINNER, "SN", 0, 0);
        board.addBall("B", R, R, 0, 0);
        SpinnerView s = spinner(board, "SN");
        for (int i = 0; i < 120; i++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", i).isEmpty();
        }
        double a = ARM;
        double b = Math.hypot(0.75, 0.75);
        double delta = Math.acos((a * a + b * b - 4 * R * R) / (2 * a * b));
        double stalledAt = Math.toRadians(225 - 180) - delta;
        assertThat(s.isStalled()).isTrue();
        assertThat(s.isMoving()).isFalse();
        // The contact is found within 1e-9 L; the gap grows by a b sin(delta) / 2r (0.68) L per radian there.
        assertThat(s.angle()).isCloseTo(stalledAt, within(1e-8));
        assertThat(board.ball("B").orElseThrow().position()).isEqualTo(new Vect(R, R));

        board.delete("B");
        board.tick(DT);
        assertThat(s.isStalled()).as("released once the ball has gone").isFalse();
        double before = s.angle();
        board.tick(DT);
        assertThat(s.angle() - before).isCloseTo(2 * Math.PI * DT, within(1e-12));
    }

    /** Sent the other way, a stalled spinner turns away from the ball that jammed it. */
    @Test
    void reversingAStalledSpinnerTurnsItAwayFromTheBall() {
        Board board = new Board();
        board.setGravity(0);
        board.addGizmo(GizmoKind.SPINNER, "SN", 0, 0);
        board.addBall("B", R, R, 0, 0);
        SpinnerView s = spinner(board, "SN");
        for (int i = 0; i < 60; i++) {
            board.tick(DT);
        }
        assertThat(s.isStalled()).isTrue();
        double stalled = s.angle();
        board.trigger("SN");
        assertThat(s.isStalled()).isFalse();
        assertThat(s.turnsPerSecond()).isEqualTo(-1);
        board.tick(DT);
        assertThat(s.angle()).isCloseTo(stalled - 2 * Math.PI * DT, within(1e-12));
        for (int i = 0; i < 120; i++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", i).isEmpty();
        }
    }

    @Test
    void stopHoldsItsAngleExactlyStartTurnsItOnAndReverseTurnsItBack() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SPINNER, "SN", 8, 8);
        board.set("SN", new Setting.Speed(0.5));
        board.bindKey(KEY, KeyEdge.DOWN, "SN", Order.of(Action.STOP));
        board.bindKey(KEY + 1, KeyEdge.DOWN, "SN", Order.of(Action.START));
        board.bindKey(KEY + 2, KeyEdge.DOWN, "SN");   // its default: reverse
        SpinnerView s = spinner(board, "SN");
        for (int i = 0; i < 10; i++) {
            board.tick(DT);
        }
        board.keyDown(KEY);
        board.keyUp(KEY);
        double stopped = s.angle();
        assertThat(stopped).isCloseTo(turned(10, 0.5), within(1e-12));
        for (int i = 0; i < 30; i++) {
            board.tick(DT);
        }
        assertThat(s.isRunning()).isFalse();
        assertThat(s.angle()).isEqualTo(stopped);
        board.keyDown(KEY + 1);
        board.keyUp(KEY + 1);
        for (int i = 0; i < 10; i++) {
            board.tick(DT);
        }
        assertThat(s.angle()).isCloseTo(turned(20, 0.5), within(1e-12));
        board.keyDown(KEY + 2);
        assertThat(s.turnsPerSecond()).isEqualTo(-0.5);
        for (int i = 0; i < 30; i++) {
            board.tick(DT);
        }
        assertThat(s.angle()).as("back through 0, to 2 pi less the 10 ticks it went on beyond")
                .isCloseTo(2 * Math.PI - turned(10, 0.5), within(1e-12));
    }

    @Test
    void aSpeedOutsideThreeTurnsASecondEitherWayOrZeroIsRefused() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SPINNER, "SN", 8, 8);
        board.addGizmo(GizmoKind.SQUARE, "S", 1, 1);
        for (double turns : new double[] {0, 3.01, -3.01, Double.NaN, Double.POSITIVE_INFINITY}) {
            org.assertj.core.api.Assertions.assertThatThrownBy(() -> board.set("SN", new Setting.Speed(turns)))
                    .isInstanceOf(BoardEditException.class).hasMessageStartingWith("a spinner turns up to 3 times");
        }
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> board.set("S", new Setting.Speed(1)))
                .isInstanceOf(BoardEditException.class).hasMessageStartingWith("only a spinner");
        board.set("SN", new Setting.Speed(-3));
        assertThat(spinner(board, "SN").turnsPerSecond()).isEqualTo(-3);
    }

    /**
     * A ball lying on a square beside the spinner, inside its box widened by a ball but out of its reach (1.42 L
     * from the pivot; the ends reach 1 + r = 1.25): awake while the spinner turns, asleep soon after it stops, and
     * woken when it starts.
     */
    @Test
    void aBallBesideItNeverSleepsWhileItTurns() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SPINNER, "SN", 5, 18);
        board.addGizmo(GizmoKind.SQUARE, "S", 4, 19);
        board.addBall("B", 4.6, 19 - R, 0, 0);
        BallView ball = board.ball("B").orElseThrow();
        for (int i = 0; i < 600; i++) {
            board.tick(DT);
            assertThat(ball.isAsleep()).as("tick %d", i).isFalse();
        }
        board.bindKey(KEY, KeyEdge.DOWN, "SN", Order.of(Action.STOP));
        board.bindKey(KEY + 1, KeyEdge.DOWN, "SN", Order.of(Action.START));
        board.keyDown(KEY);
        for (int i = 0; i < 600 && !ball.isAsleep(); i++) {
            board.tick(DT);
        }
        assertThat(ball.isAsleep()).as("asleep once the spinner stopped").isTrue();
        board.keyDown(KEY + 1);
        assertThat(ball.isAsleep()).as("woken when it starts").isFalse();
        assertThat(ball.position()).isEqualTo(new Vect(4.6, 19 - R));
    }

    /**
     * 100,000 ticks (some 28 minutes of play) of balls thrown among spinners turning both ways at different speeds,
     * reversed, stopped and started at random: no ball is ever inside a spinner's bar, by the test's own geometry
     * (the distance from the ball's centre to the segment between the ends, less the end's radius, at least r).
     */
    @Test
    void ballsAmongSpinnersForAHundredThousandTicksNeverEndInsideOne() {
        Random random = new Random(22);
        Board board = new Board();
        board.setGravity(0);
        board.setFriction(0, 0);
        String[] spinners = {"SN1", "SN2", "SN3", "SN4", "SN5", "SN6", "SN7"};
        int[][] cells = {{0, 0}, {4, 3}, {9, 9}, {11, 9}, {15, 4}, {18, 18}, {6, 15}};
        double[] speeds = {1, -1, 3, -3, 0.5, 2, -0.25};
        for (int i = 0; i < spinners.length; i++) {
            board.addGizmo(GizmoKind.SPINNER, spinners[i], cells[i][0], cells[i][1]);
            board.set(spinners[i], new Setting.Speed(speeds[i]));
        }
        board.addGizmo(GizmoKind.SQUARE, "S1", 13, 9);   // a pocket beside SN4
        board.addGizmo(GizmoKind.TRIANGLE, "T1", 8, 10);  // and one beside SN3
        board.addGizmo(GizmoKind.SQUARE, "S2", 17, 18);
        for (int b = 0; b < 10; b++) {
            board.addBall("B" + b, 1.5 + 1.8 * b, 13, 15 * random.nextGaussian(), 15 * random.nextGaussian());
        }
        Action[] actions = {Action.REVERSE, Action.START, Action.STOP, Action.START};
        for (int k = 0; k < spinners.length; k++) {
            for (int a = 0; a < actions.length; a++) {
                board.bindKey(KEY + k * actions.length + a, KeyEdge.DOWN, spinners[k], Order.of(actions[a]));
            }
        }
        double deepest = 0;
        for (int tick = 0; tick < 100_000; tick++) {
            if (random.nextInt(30) == 0) {
                int key = KEY + random.nextInt(spinners.length * actions.length);
                board.keyDown(key);
                board.keyUp(key);
            }
            board.tick(DT);
            for (String name : spinners) {
                SpinnerView s = spinner(board, name);
                for (BallView ball : board.balls()) {
                    deepest = Math.max(deepest, R - distanceToBar(s, ball.position()));
                }
            }
            if (tick % 1000 == 0) {
                assertThat(Invariants.violations(board)).as("tick %d", tick).isEmpty();
            }
        }
        assertThat(deepest).as("deepest a ball went into a bar").isLessThanOrEqualTo(1e-6);
        assertThat(board.balls()).hasSize(10);
    }

    /**
     * The distance from p to the bar at its angle, the test's own geometry: the bar's ends are 0.75 either side of
     * the pivot along (cos angle, sin angle), and the bar is every point within 0.25 of the segment between them.
     */
    private static double distanceToBar(SpinnerView s, Vect p) {
        double cx = s.pivot().x();
        double cy = s.pivot().y();
        double ux = Math.cos(s.angle());
        double uy = Math.sin(s.angle());
        double along = Math.max(-ARM, Math.min(ARM, (p.x() - cx) * ux + (p.y() - cy) * uy));
        return Math.hypot(p.x() - cx - along * ux, p.y() - cy - along * uy) - END_RADIUS;
    }
}
