package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.LoopMode;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import physics.Vect;

/** Free flight, friction, walls and energy, against closed forms of the loop's integration. */
class BallMotionTest {
    private static final double DT = Board.DEFAULT_TICK;

    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void freeFallFollowsTheSemiImplicitEulerClosedForm(LoopMode mode) {
        Board board = new Board();
        board.setLoopMode(mode);
        board.setFriction(0, 0);
        double g = 25;
        double x0 = 4;
        double y0 = 1;
        double vx = 3;
        double vy0 = -6;
        board.addBall("B", x0, y0, vx, vy0);
        int n = 50;
        for (int i = 0; i < n; i++) {
            board.tick(DT);
        }
        // stage 1 first: v_k = vy0 + k g dt, and the ball moves v_k dt in tick k, so
        // y_n = y0 + n vy0 dt + g dt^2 n(n+1)/2
        BallView ball = board.ball("B").orElseThrow();
        assertThat(ball.velocity().y()).isCloseTo(vy0 + n * g * DT, within(1e-9));
        assertThat(ball.velocity().x()).isCloseTo(vx, within(1e-12));
        assertThat(ball.position().y()).isCloseTo(y0 + n * vy0 * DT + g * DT * DT * n * (n + 1) / 2.0, within(1e-9));
        assertThat(ball.position().x()).isCloseTo(x0 + n * vx * DT, within(1e-9));
        assertThat(board.time()).isCloseTo(n * DT, within(1e-12));
    }

    @Test
    void frictionSlowsAFreeBallByTheSpecFormula() {
        Board board = new Board();
        board.setGravity(0);
        double mu = 0.5;
        double mu2 = 0.1;
        board.setFriction(mu, mu2);
        board.addBall("B", 2, 10, 12, 5);
        double speed = 13;
        double travelled = 0;
        for (int i = 0; i < 30; i++) {
            board.tick(DT);
            speed = speed * (1 - mu * DT - mu2 * speed * DT);
            travelled += speed * DT;
        }
        BallView ball = board.ball("B").orElseThrow();
        assertThat(ball.velocity().length()).isCloseTo(speed, within(1e-9));
        assertThat(ball.velocity().x() / ball.velocity().y()).isCloseTo(12.0 / 5, within(1e-12));
        assertThat(ball.position().minus(new Vect(2, 10)).length()).isCloseTo(travelled, within(1e-9));
    }

    /** The position of a ball bouncing elastically between walls at r and SIZE - r: a triangle wave. */
    private static double folded(double start, double velocity, double t) {
        double lo = Board.BALL_RADIUS;
        double span = Board.SIZE - 2 * lo;
        double u = ((start - lo + velocity * t) % (2 * span) + 2 * span) % (2 * span);
        return lo + (u <= span ? u : 2 * span - u);
    }

    @Test
    void anElasticBallInTheEmptyBoxFollowsTheFoldedStraightLine() {
        Board board = new Board();
        board.setGravity(0);
        board.setFriction(0, 0);
        double vx = 37.3;
        double vy = -21.9;
        board.addBall("B", 3.3, 8.1, vx, vy);
        for (int i = 1; i <= 600; i++) {
            board.tick(DT);
            BallView ball = board.ball("B").orElseThrow();
            double t = i * DT;
            assertThat(ball.position().x()).as("tick %d", i).isCloseTo(folded(3.3, vx, t), within(1e-9));
            assertThat(ball.position().y()).as("tick %d", i).isCloseTo(folded(8.1, vy, t), within(1e-9));
            assertThat(ball.velocity().length()).isCloseTo(Math.hypot(vx, vy), within(1e-9));
        }
    }

    @Test
    void theSeedLoopLosesTheRestOfATickAtACollisionAndTheContinuousOneDoesNot() {
        double[] afterOneTick = new double[2];
        for (LoopMode mode : LoopMode.values()) {
            Board board = new Board();
            board.setLoopMode(mode);
            board.setGravity(0);
            board.setFriction(0, 0);
            board.addBall("B", 19.65, 10, 12, 0);   // reaches the wall (x = 19.75) after 0.1/12 s
            board.tick(DT);
            afterOneTick[mode.ordinal()] = board.ball("B").orElseThrow().position().x();
        }
        assertThat(afterOneTick[LoopMode.SEED.ordinal()]).isCloseTo(19.75, within(1e-12));
        assertThat(afterOneTick[LoopMode.CONTINUOUS.ordinal()]).isCloseTo(19.75 - (12 * DT - 0.1), within(1e-12));
    }

    @Test
    void zeroTickChangesNothing() {
        Board board = BoardEditingTest.sample();
        String before = BoardSnapshot.of(board);
        List<BoardChange> seen = new ArrayList<>();
        board.addObserver((b, c) -> seen.add(c));
        board.tick(0);
        assertThat(BoardSnapshot.of(board)).isEqualTo(before);
        assertThat(seen).containsExactly(BoardChange.TICK);
    }

    /**
     * Energy bound for the loop's integration. Semi-implicit Euler (gravity, then a straight move) keeps the shadow
     * energy S = |v + g dt/2 y|^2/2 - g y exactly in free flight; elastic bounces keep the balls' total S because
     * the loop rescales after them (TickRun). energy() = sum(|v|^2/2 - g y) + const = S - (g dt/2) sum(v_y) + const,
     * so E_n - E_0 = -(g dt/2) sum(v_y,n - v_y,0) <= g dt * (number of balls) * max|v_y|.
     */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void energyOfElasticFrictionlessBouncingStaysWithinTheIntegrationBound(LoopMode mode) {
        Board board = new Board();
        board.setLoopMode(mode);
        board.setFriction(0, 0);
        board.addGizmo(GizmoKind.CIRCLE, "C", 12, 12);
        board.addGizmo(GizmoKind.TRIANGLE, "T", 5, 15);
        board.addGizmo(GizmoKind.SQUARE, "S", 15, 6);
        board.addBall("B", 10.2, 3.7, 7, 0);
        board.addBall("D", 4.6, 8.1, -3, 2);
        double g = board.gravity();
        double e0 = board.energy();
        double maxVy = 2;
        for (int i = 0; i < 100_000; i++) {
            board.tick(DT);
            for (BallView ball : board.balls()) {
                maxVy = Math.max(maxVy, Math.abs(ball.velocity().y()));
            }
            assertThat(board.energy()).as("tick %d", i).isLessThanOrEqualTo(e0 + g * DT * 2 * maxVy + 1e-9);
            assertThat(Invariants.violations(board)).as("tick %d", i).isEmpty();
        }
    }

    @Test
    void aBouncingBallsApexDoesNotClimb() {
        Board board = new Board();
        board.setFriction(0, 0);
        double y0 = 5.123;
        board.addBall("B", 10, y0, 0, 0);
        List<Double> apexes = new ArrayList<>();
        double previousVy = 0;
        for (int i = 0; i < 60 * 60; i++) {
            board.tick(DT);
            BallView ball = board.ball("B").orElseThrow();
            if (previousVy < 0 && ball.velocity().y() >= 0) {
                apexes.add(ball.position().y());
            }
            previousVy = ball.velocity().y();
        }
        assertThat(apexes).hasSizeGreaterThan(20);
        // The tick-boundary positions lie on the shadow parabola of the start, whose velocity at a boundary is
        // v + g dt/2 (v: the velocity of the tick just ended) and whose peak is at y0 - (g dt/2)^2/(2g) =
        // y0 - g dt^2/8. The sample taken is the first after v turned >= 0, where the parabola's velocity is in
        // [g dt/2, 3 g dt/2): between dt/2 and 3 dt/2 past the peak, so g dt^2/8 to 9 g dt^2/8 below it
        // (y grows downward). Any climbing over the bounces would break the lower bound.
        double g = board.gravity();
        double peak = y0 - g * DT * DT / 8;
        assertThat(apexes).allSatisfy(apex -> assertThat(apex)
                .isBetween(peak + g * DT * DT / 8 - 1e-9, peak + 9 * g * DT * DT / 8 + 1e-9));
    }
}
