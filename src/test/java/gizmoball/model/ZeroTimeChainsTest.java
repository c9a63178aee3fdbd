package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.GuardCounts;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import physics.Vect;

/**
 * Chains of collisions at no time apart that once ran into the wedge guard (docs/design.md, "Resting and rolling
 * contact", "Guards"): a pile on a support that moves, a ball rolling under an overhang, a ball driven into a narrow
 * wedge. Each ends as its limit says, in one collision or a few, with no guard.
 */
class ZeroTimeChainsTest {
    private static final double DT = 1.0 / 60;
    private static final double R = Board.BALL_RADIUS;

    /**
     * A ball S lies on a circle bumper off its top, another T on S: S rolls off, carrying T. Each time S presses T
     * and the circle takes S's push, the pair closes again a little less: the pile's velocities settle in one
     * collision instead of a chain of them.
     */
    @ParameterizedTest(name = "S {0} degrees off the top")
    @ValueSource(doubles = {5, 10, 20, 30})
    void aPileOnABallRollingOffACircleSettlesWithoutAChain(double degrees) {
        Board board = new Board();
        board.addGizmo(GizmoKind.CIRCLE, "C", 10, 15);
        double s = Math.toRadians(degrees);
        double sx = 10.5 + (0.5 + R) * Math.sin(s);
        double sy = 15.5 - (0.5 + R) * Math.cos(s);
        board.addBall("S", sx, sy, 0, 0);
        board.addBall("T", sx + 2 * R * Math.sin(s + 0.3), sy - 2 * R * Math.cos(s + 0.3), 0, 0);
        double start = board.energy();
        for (int t = 0; t < 600; t++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", t).isEmpty();
            assertThat(board.lastTick().zeroTimeCollisions()).as("tick %d", t).isLessThanOrEqualTo(2);
            assertThat(board.energy()).as("tick %d", t).isLessThanOrEqualTo(start + 1e-9);
        }
        assertThat(board.guardsFired()).isEqualTo(GuardCounts.NONE);
    }

    /** A floor of squares from wall to wall, its top at y = 18: nothing falls off it. */
    private static void floor(Board board) {
        for (int x = 0; x < Board.SIZE; x++) {
            board.addGizmo(GizmoKind.SQUARE, "S" + x, x, 18);
        }
    }

    /**
     * Puts a flipper at an angle and holds it there, as a ball jammed against it would: blocked until no ball touches
     * it. Blocking is the loop's act, so the test reaches the flipper as the loop does, through the board's loop view,
     * not by casting the read-only gizmo the board hands its users.
     */
    private static void holdStill(Board board, String flipper, double degrees) {
        board.setFlipperState(flipper, degrees, true);
        board.loopView().movingShapes().stream().filter(f -> f.name().equals(flipper)).findFirst().orElseThrow().stall();
    }

    /** A left flipper at (10,16) held still at an angle: the centre of its round tip. */
    private static Vect tip(double degrees) {
        double theta = Math.toRadians(degrees);
        return new Vect(10.25 + 1.5 * Math.sin(theta), 16.25 + 1.5 * Math.cos(theta));
    }

    /**
     * A floor of squares (top y = 18) and a left flipper held at 46.1 degrees, its tip just low enough that a ball
     * rolling along the floor meets it on its lower half. A second ball lying on the tip against a square keeps the
     * flipper blocked (a flipper stopped by a ball stays put while the ball touches it).
     */
    private static Board underAnOverhang(double speed) {
        Board board = new Board();
        board.setFriction(0, 0);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 10, 16);
        floor(board);
        board.addGizmo(GizmoKind.SQUARE, "W", 12, 17);
        holdStill(board, "F", 46.1);
        Vect tip = tip(46.1);
        double holderX = 12 - R;
        board.addBall("H", holderX, tip.y() - Math.sqrt(4 * R * R - Math.pow(holderX - tip.x(), 2)), 0, 0);
        board.addBall("B", 8.5, 18 - R, speed, 0);
        return board;
    }

    /**
     * Rolling at u into the tip, the ball meets it with normal n (from the tip's centre to the ball's). The bounce
     * (coefficient 0.95) sends it down into the floor at 1.95 u |n.x| n.y. Below two ticks of gravity the floor takes
     * that as resting contact, and what is left, u (1 - 1.95 n.x^2) along the floor, still closes on the tip: each
     * round would leave a fraction of the last, for ever. The limit is rest, touching both.
     */
    @ParameterizedTest(name = "at {0} L/s")
    @ValueSource(doubles = {0.6, 1.0})
    void aBallRollingSlowlyUnderAnOverhangStopsAgainstItAndTheFloor(double speed) {
        Vect tip = tip(46.1);
        double dy = (18 - R) - tip.y();
        double dx = Math.sqrt(4 * R * R - dy * dy);
        Vect n = new Vect(-dx, dy).times(1 / (2 * R));
        assertThat(1.95 * speed * -n.x() * n.y()).as("into the floor").isLessThan(2 * 25 * DT);
        assertThat(1 - 1.95 * n.x() * n.x()).as("still closing after the floor took its part").isPositive();

        Board board = underAnOverhang(speed);
        for (int t = 0; t < 400; t++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", t).isEmpty();
            assertThat(board.lastTick().zeroTimeCollisions()).as("tick %d", t).isLessThanOrEqualTo(3);
        }
        BallView ball = board.ball("B").orElseThrow();
        assertThat(ball.velocity()).isEqualTo(Vect.ZERO);
        assertThat(ball.position().x()).isCloseTo(tip.x() - dx, within(1e-9));
        assertThat(ball.position().y()).isCloseTo(18 - R, within(1e-9));
        assertThat(board.guardsFired()).isEqualTo(GuardCounts.NONE);
    }

    /** Faster, the bounce leaves the floor too (faster than two ticks of gravity): the ball comes back out. */
    @ParameterizedTest(name = "at {0} L/s")
    @ValueSource(doubles = {1.5, 3})
    void aBallRollingFastUnderAnOverhangBouncesBackOut(double speed) {
        Board board = underAnOverhang(speed);
        double start = board.energy();
        boolean cameBack = false;
        for (int t = 0; t < 400; t++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", t).isEmpty();
            assertThat(board.energy()).as("tick %d", t).isLessThanOrEqualTo(start + 1e-9);
            cameBack |= board.ball("B").orElseThrow().velocity().x() < 0;
        }
        assertThat(cameBack).isTrue();
        assertThat(board.guardsFired()).isEqualTo(GuardCounts.NONE);
    }

    /**
     * A ball W lies on the floor touching the tip of a held flipper from the left, the two surfaces meeting at
     * {@code degrees}. Another ball strikes W at 20 L/s straight into that wedge. One contact at a time, an elastic
     * ball turns back in a wedge only after about 180 / degrees bounces, all at no time apart; the cluster of W's
     * contacts is solved at once instead (docs/design.md, "Contact clusters"): the chain ends at its second
     * collision, the impact comes back out to A, with no guard and no energy gained.
     */
    @ParameterizedTest(name = "wedge of {0} degrees")
    @ValueSource(doubles = {2, 3})
    void aBallDrivenIntoANarrowWedgeBouncesThroughItWithoutTheGuard(double degrees) {
        Board board = new Board();
        board.setFriction(0, 0);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 10, 16);
        floor(board);
        double alpha = Math.toRadians(degrees);
        double tipY = 18 - R - 2 * R * Math.cos(alpha);
        double angle = Math.toDegrees(Math.acos((tipY - 16.25) / 1.5));
        holdStill(board, "F", angle);
        board.addBall("W", tip(angle).x() - 2 * R * Math.sin(alpha), 18 - R, 0, 0);
        board.addBall("A", 5, 18 - R, 20, 0);
        double start = board.energy();
        int longestChain = 0;
        double slowestA = Double.POSITIVE_INFINITY;
        for (int t = 0; t < 120; t++) {
            board.tick(DT);
            slowestA = Math.min(slowestA, board.ball("A").orElseThrow().velocity().x());
            assertThat(Invariants.violations(board)).as("tick %d", t).isEmpty();
            assertThat(board.energy()).as("tick %d", t).isLessThanOrEqualTo(start + 1e-9);
            longestChain = Math.max(longestChain, board.lastTick().zeroTimeCollisions());
        }
        assertThat(longestChain).isLessThanOrEqualTo(2);
        assertThat(board.guardsFired()).isEqualTo(GuardCounts.NONE);
        assertThat(slowestA).as("the impact came back out of the wedge to A").isLessThan(0);
    }

    /**
     * Two balls far apart dropped from the same height meet the floor at the same instant: no chain, so neither
     * collision is at zero time; the second is counted as at once apart. From 10 L up they fall 9.75 L onto the
     * bottom wall at sqrt(2 g 9.75) = 22 L/s, far above resting.
     */
    @Test
    void ballsApartMeetingTheFloorAtOnceAreNoChain() {
        Board board = new Board();
        board.addBall("A", 5, 10, 0, 0);
        board.addBall("B", 15, 10, 0, 0);
        int collisions = 0;
        int simultaneous = 0;
        for (int t = 0; t < 60; t++) {
            board.tick(DT);
            assertThat(board.lastTick().zeroTimeCollisions()).as("tick %d", t).isZero();
            collisions += board.lastTick().collisions();
            simultaneous += board.lastTick().simultaneousCollisions();
        }
        assertThat(collisions).isEqualTo(2);
        assertThat(simultaneous).isEqualTo(1);
    }
}
