package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.Invariants;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.GizmoKind;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import physics.Vect;

/**
 * A ball between a swinging flipper and what it came back from (docs/design.md, "Pinched balls"): squeezed out
 * where a way out exists, jamming the flipper where none does; no guard either way.
 */
class PinchedBallsTest {
    private static final double DT = 1.0 / 60;
    private static final double OMEGA = Math.toRadians(1080);

    private static int jams(Board board) {
        return (int) board.lastTick().events().stream().filter(e -> e instanceof PlayEvent.Jammed).count();
    }

    /**
     * The flipper's tip bats a ball into the face of a square beside it; the ball comes straight back and the
     * flipper, still swinging, meets it again. There is a way out, along the face, faster than any point of the
     * flipper moves (the seed squeezed from between two fingers): the ball takes it and the flipper swings on to
     * its stop on time, (90 - 10) / 1080 s.
     */
    @Test
    void aBallBetweenTheTipAndAFaceIsSqueezedOutAndTheFlipperSwingsOn() {
        Board board = new Board();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 4, 16);
        board.addGizmo(GizmoKind.SQUARE, "W", 6, 17);
        board.setFlipperState("F", 10, true);
        board.addBall("B", 5.6, 17.2, 0, 0);
        FlipperView flipper = (FlipperView) board.gizmo("F").orElseThrow();
        double fastestUp = 0;
        int jams = 0;
        for (int t = 0; t < 30; t++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", t).isEmpty();
            jams += jams(board);
            fastestUp = Math.max(fastestUp, -board.ball("B").orElseThrow().velocity().y());
            if (t == (int) Math.ceil(80.0 / 1080 / DT)) {
                assertThat(flipper.angleFromRest()).as("on time").isEqualTo(90.0);
            }
        }
        assertThat(jams).isZero();
        assertThat(board.guardsFired()).isEqualTo(GuardCounts.NONE);
        assertThat(fastestUp).isGreaterThan(OMEGA * (1.5 + flipper.radius())).isLessThanOrEqualTo(Board.MAX_SPEED);
    }

    /**
     * A ball lying in the pocket between two circle bumpers and a square's corner, in the path of the flipper's tip
     * swinging down: no way out, so the flipper stops where it meets the ball, once, and stays there, the ball still,
     * until it is sent the other way.
     */
    @Test
    void aBallInAPocketJamsTheFlipperUntilItIsSentBack() {
        Board board = new Board();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 4, 16);
        board.addGizmo(GizmoKind.CIRCLE, "C3_17", 3, 17);
        board.addGizmo(GizmoKind.SQUARE, "S3_18", 3, 18);
        board.addGizmo(GizmoKind.CIRCLE, "C4_18", 4, 18);
        board.bindKey(90, KeyEdge.DOWN, "LF");
        board.bindKey(90, KeyEdge.UP, "LF");
        board.setFlipperState("LF", 90, true);
        double offset = Board.BALL_RADIUS / Math.sqrt(2);   // touching the square's corner (4, 18), on the diagonal
        board.addBall("B", 4 + offset, 18 - offset, 0, 0);
        for (int t = 0; t < Math.round(LoopSettings.STANDARD.sleepTime() / DT) + 5; t++) {
            board.tick(DT);
        }
        Vect lying = board.ball("B").orElseThrow().position();
        board.keyUp(90);
        FlipperView flipper = (FlipperView) board.gizmo("LF").orElseThrow();
        int jams = 0;
        double jammedAt = Double.NaN;
        Vect held = null;
        for (int t = 0; t < 120; t++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", t).isEmpty();
            jams += jams(board);
            Vect now = board.ball("B").orElseThrow().position();
            if (jams == 1 && held == null) {
                jammedAt = flipper.angleFromRest();
                held = now;
            } else if (held != null) {
                assertThat(now).as("tick %d: held where it jammed", t).isEqualTo(held);
            }
        }
        assertThat(jams).isEqualTo(1);
        assertThat(jammedAt).isStrictlyBetween(0.0, 90.0);
        assertThat(flipper.angleFromRest()).isEqualTo(jammedAt);
        // the strike that found the jam may nudge the ball within the pocket, no more
        assertThat(held.minus(lying).length()).isLessThan(0.01);
        assertThat(board.guardsFired()).isEqualTo(GuardCounts.NONE);
        board.keyDown(90);
        for (int t = 0; t < 10; t++) {
            board.tick(DT);
        }
        assertThat(flipper.angleFromRest()).isEqualTo(90.0);
    }

    /**
     * Two balls in that pocket (stress.txt's, with the square under it gone): A lies in the notch where the circles
     * meet, B lies on A, and the flipper swings down onto B. Struck one at a time, A and B would rattle between the
     * circles, each other and the flipper, every strike of the swinging flipper sending them back faster and the
     * strikes ever closer together (stress.txt had 160 a tick, at up to 110 L/s). Their limit is the pair carried in
     * contact: once a ball rattles the cluster is solved inelastic, so a tick never holds many more collisions than
     * the rattle takes to be seen.
     */
    @Test
    void twoBallsInAPocketUnderASwingingFlipperAreCarriedNotRattled() {
        Board board = new Board();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 4, 16);
        board.addGizmo(GizmoKind.CIRCLE, "C3_17", 3, 17);
        board.addGizmo(GizmoKind.CIRCLE, "C4_18", 4, 18);
        board.bindKey(90, KeyEdge.DOWN, "LF");
        board.bindKey(90, KeyEdge.UP, "LF");
        board.setFlipperState("LF", 90, true);
        // the circles' centres (3.5, 17.5) and (4.5, 18.5) meet at (4, 18); A touches both, up and to the right
        double r = Board.BALL_RADIUS;
        double along = Math.sqrt((0.5 + r) * (0.5 + r) - 0.5) / Math.sqrt(2);
        board.addBall("A", 4 + along, 18 - along, 0, 0);
        board.addBall("B", 4 + along + 2 * r * Math.cos(0.3), 18 - along - 2 * r * Math.sin(0.3), 0, 0);
        board.keyUp(90);
        int most = 0;
        for (int t = 0; t < 120; t++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", t).isEmpty();
            most = Math.max(most, board.lastTick().collisions());
        }
        assertThat(most).isLessThanOrEqualTo(3 * LoopSettings.STANDARD.rattleCollisions());
        assertThat(board.guardsFired()).isEqualTo(GuardCounts.NONE);
    }

    /**
     * Two flippers side by side swinging up together close on a ball between them like tongs. Bounced from one to
     * the other in a closing gap it would be struck ever faster; coming back from the other flipper is coming back
     * from something, so it is squeezed out, or jams the pair. No guard, a handful of collisions a tick at most.
     */
    @ParameterizedTest(name = "ball at ({0}, {1})")
    @MethodSource("betweenTheTongs")
    void aBallBetweenTwoFlippersClosingOnItIsSqueezedOutOrJamsThem(double x, double y) {
        Board board = new Board();
        board.setGravity(0);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "L", 8, 10);
        board.addGizmo(GizmoKind.RIGHT_FLIPPER, "R", 10, 10);
        board.addBall("B", x, y, 0, 0);
        board.bindKey(32, KeyEdge.DOWN, "L");
        board.bindKey(32, KeyEdge.DOWN, "R");
        board.keyDown(32);
        for (int t = 0; t < 30; t++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).as("tick %d", t).isEmpty();
            assertThat(board.lastTick().collisions()).as("tick %d", t).isLessThanOrEqualTo(20);
        }
        assertThat(board.guardsFired()).isEqualTo(GuardCounts.NONE);
    }

    static Stream<Arguments> betweenTheTongs() {
        List<Arguments> starts = new ArrayList<>();
        for (int i = 0; i <= 8; i++) {
            for (int j = 0; j <= 8; j++) {
                starts.add(Arguments.of(9.6 + 0.1 * i, 10.5 + 0.15 * j));
            }
        }
        return starts.stream();
    }
}
