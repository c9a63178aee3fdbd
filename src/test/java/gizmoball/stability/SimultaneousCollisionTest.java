package gizmoball.stability;

import gizmoball.model.Board;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.LoopMode;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import physics.Vect;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

/**
 * Failure mode: two collisions at the same instant. Whichever is resolved first, the other must follow at
 * time 0 (in the SEED loop, in the next tick), not be lost or pass through. Without gravity or friction
 * the outcomes are exact: a ball meeting two perpendicular walls at once comes straight back along its
 * path; a ball striking two touching balls conserves momentum and energy.
 */
class SimultaneousCollisionTest {

    private static final double DT = Board.DEFAULT_TICK;
    private static final double R = Board.BALL_RADIUS;

    /** Into the board's bottom-right corner along the diagonal: both walls at once, straight back out. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void ballIntoTheBoardCornerComesStraightBack(LoopMode mode) {
        Board board = FreeSpace.board(mode);
        board.addBall("B", 15.3, 15.3, 6, 6);
        new Watch("board corner", board, DT).run(180, (tick, b) -> {
            BallView ball = b.balls().get(0);
            assertThat(ball.position().x()).as("on the diagonal at tick " + tick).isCloseTo(ball.position().y(), within(1e-9));
        });
        // 180 ticks = 3 s: 4.45 L in, 13.55 L back out along the diagonal.
        assertThat(board.balls().get(0).velocity().x()).isCloseTo(-6, within(1e-9));
        assertThat(board.balls().get(0).velocity().y()).isCloseTo(-6, within(1e-9));
    }

    /**
     * Squares at (9,10) and (10,9) touch corner to corner at (10,10): below-right of that point their
     * faces x = 10 and y = 10 form a 90-degree corner. A ball along the diagonal meets both faces at once.
     */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void ballIntoTheCornerBetweenTwoSquaresComesStraightBack(LoopMode mode) {
        Board board = FreeSpace.board(mode);
        board.addGizmo(GizmoKind.SQUARE, "A", 9, 10);
        board.addGizmo(GizmoKind.SQUARE, "B", 10, 9);
        board.addBall("ball", 12.4, 12.4, -5, -5);
        new Watch("corner between squares", board, DT).run(60, (tick, b) -> {
            BallView ball = b.balls().get(0);
            assertThat(ball.position().x()).as("on the diagonal at tick " + tick).isCloseTo(ball.position().y(), within(1e-9));
            assertThat(Math.min(ball.position().x(), ball.position().y())).as("outside both squares at tick " + tick)
                    .isGreaterThanOrEqualTo(10 + R - 1e-6);
        });
        // 60 ticks = 1 s: 2.15 L in at 5 L/s per axis, then back out.
        BallView ball = board.balls().get(0);
        assertThat(ball.velocity().x()).isCloseTo(5, within(1e-9));
        assertThat(ball.velocity().y()).isCloseTo(5, within(1e-9));
    }

    /** A ball strikes two touching balls symmetrically, meeting both at the same instant. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void ballStrikingTwoTouchingBallsConservesMomentumAndEnergy(LoopMode mode) {
        Board board = FreeSpace.board(mode);
        board.addBall("upper", 10, 10 - R, 0, 0);
        board.addBall("lower", 10, 10 + R, 0, 0);
        board.addBall("striker", 5, 10, 10, 0);
        double e0 = board.energy();
        // 60 ticks = 1 s: contact after about 0.46 s; nobody reaches a wall before 1 s.
        new Watch("striking two touching balls", board, DT).run(60, (tick, b) -> {
            Vect momentum = Vect.ZERO;
            for (BallView ball : b.balls()) {
                momentum = momentum.plus(ball.velocity());
            }
            assertThat(momentum.x()).as("momentum x at tick " + tick).isCloseTo(10, within(1e-9));
            assertThat(momentum.y()).as("momentum y at tick " + tick).isCloseTo(0, within(1e-9));
            assertThat(b.energy()).as("energy at tick " + tick).isCloseTo(e0, within(1e-9 * e0));
        });
        // Each struck ball leaves along its line of centres with the striker, 30 degrees off the striker's path
        // (sin 30 = R / 2R). However the two same-instant contacts are resolved, one after the other or together,
        // a struck ball gets at most the striker's whole normal part, 10 cos 30, and at least what the second of
        // two sequential impacts passes on, 10 cos 30 / 2 (together: 10 * 2 sqrt 3 / 5 each, in between).
        double most = 10 * Math.cos(Math.toRadians(30));
        Vect upward = new Vect(Math.cos(Math.toRadians(30)), -Math.sin(Math.toRadians(30)));
        Vect downward = new Vect(upward.x(), -upward.y());
        Vect upper = board.balls().get(0).velocity();
        Vect lower = board.balls().get(1).velocity();
        assertThat(upper.length()).as("the upper ball was struck").isBetween(most / 2 - 1e-9, most + 1e-9);
        assertThat(lower.length()).as("the lower ball was struck").isBetween(most / 2 - 1e-9, most + 1e-9);
        assertThat(upper.unitSize().minus(upward).length()).as("upper along its line of centres").isLessThan(1e-9);
        assertThat(lower.unitSize().minus(downward).length()).as("lower along its line of centres").isLessThan(1e-9);
    }
}
