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
 * Failure mode (docs/design.md, "Failure modes": seams between gizmos): seams between adjacent gizmos. Where two squares meet, their corner circles
 * lie exactly on the flat surface; a ball crossing the seam touches them tangentially, which is no
 * collision. It must not snag (lose speed, be kicked up) on them.
 */
class SeamTest {

    private static final double DT = Board.DEFAULT_TICK;
    private static final double R = Board.BALL_RADIUS;
    /**
     * Passing a seam's corner circle is a tangent contact, a double root of the collision quadratic, whose
     * time is known only to about the square root of the machine epsilon: a deflection that small is
     * rounding; a snag is orders of magnitude larger.
     */
    private static final double TANGENT = 1e-6;

    private static Board rowOfSquares(LoopMode mode) {
        Board board = new Board();
        LoopModes.set(board, mode);
        for (int x = 4; x < 16; x++) {
            board.addGizmo(GizmoKind.SQUARE, "S" + x, x, 12);
        }
        return board;
    }

    /** Without gravity or friction: gliding along the top of the row, touching it, nothing changes at all. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void glidingAcrossSeamsChangesNothing(LoopMode mode) {
        Board board = rowOfSquares(mode);
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addBall("glider", 4.5, 12 - R, 6, 0);
        // 90 ticks = 1.5 s: 9 L along the row, across nine seams, still above it.
        new Watch("gliding across seams", board, DT).run(90, (tick, b) -> {
            BallView ball = b.balls().get(0);
            assertThat(ball.position().y()).as("height at tick " + tick).isCloseTo(12 - R, within(TANGENT));
            assertThat(ball.velocity().x()).as("vx at tick " + tick).isCloseTo(6, within(TANGENT));
            assertThat(ball.velocity().y()).as("vy at tick " + tick).isCloseTo(0, within(TANGENT));
        });
    }

    /** Rolling under gravity and friction along the row: it stays on top, is never kicked up, keeps going. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void rollingAcrossSeamsUnderGravityDoesNotSnag(LoopMode mode) {
        Board board = rowOfSquares(mode);
        board.addBall("roller", 4.5, 12 - R, 6, 0);
        double g = board.gravity();
        double hop = g * DT * DT;
        double[] expectedVx = {6};
        new Watch("rolling across seams", board, DT).allowEnergyGainOfOneTickAt(6 + g * DT).run(90, (tick, b) -> {
            BallView ball = b.balls().get(0);
            assertThat(ball.position().y()).as("height at tick " + tick).isBetween(12 - R - hop - 1e-9, 12 - R + 1e-6);
            assertThat(Math.abs(ball.velocity().y())).as("vertical speed at tick " + tick).isLessThanOrEqualTo(g * DT + 1e-9);
            // Friction alone, docs/rules.md's V (1 - mu dt - mu2 |V| dt) each tick; |V| includes the small vertical
            // speed of resting contact (at most g dt), which shifts vx by far less than 0.01 over 90 ticks.
            expectedVx[0] *= 1 - b.mu() * DT - b.mu2() * expectedVx[0] * DT;
            assertThat(ball.velocity().x()).as("vx at tick " + tick).isCloseTo(expectedVx[0], within(0.01));
        });
    }

    /**
     * Along the 45-degree slope of three triangles (seams at (8,12) and (9,13)), without gravity: touching
     * the slope and moving along it, the ball keeps exactly its distance and its velocity.
     */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void glidingDownASlopeOfTrianglesAcrossSeamsChangesNothing(LoopMode mode) {
        Board board = CornerAndWedgeTest.vOfTriangles();
        LoopModes.set(board, mode);
        board.setGravity(0);
        board.setFriction(0, 0);
        double off = R / Math.sqrt(2);   // from the slope y = x + 4 along its free-side normal (1, -1)/sqrt 2
        double v = 3;                    // along the slope, (1, 1)/sqrt 2
        board.addBall("glider", 7.3 + off, 11.3 - off, v / Math.sqrt(2), v / Math.sqrt(2));
        // 50 ticks = 0.83 s: 2.5 L down the slope, to just short of the bottom of the V at (10, 14).
        new Watch("gliding down a slope of triangles", board, DT).run(50, (tick, b) -> {
            BallView ball = b.balls().get(0);
            double distance = (ball.position().x() + 4 - ball.position().y()) / Math.sqrt(2);
            assertThat(distance).as("distance from the slope at tick " + tick).isCloseTo(R, within(TANGENT));
            assertThat(ball.velocity().x()).as("vx at tick " + tick).isCloseTo(v / Math.sqrt(2), within(TANGENT));
            assertThat(ball.velocity().y()).as("vy at tick " + tick).isCloseTo(v / Math.sqrt(2), within(TANGENT));
        });
    }
}
