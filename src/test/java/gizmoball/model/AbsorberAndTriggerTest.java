package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.TriggerSource;

import org.junit.jupiter.api.Test;

import physics.Vect;

/** Absorbers, triggers, connections, key bindings and the flipper's swing timing. */
class AbsorberAndTriggerTest {
    private static final double DT = Board.DEFAULT_TICK;

    private static Board boardWithAbsorber() {
        Board board = new Board();
        board.addAbsorber("A", 0, 18, 20, 20);
        return board;
    }

    private static void tickUntilCaptured(Board board, String ball) {
        for (int i = 0; i < 300 && !board.ball(ball).orElseThrow().isCaptured(); i++) {
            board.tick(DT);
        }
        assertThat(board.ball(ball).orElseThrow().isCaptured()).as(ball + " captured").isTrue();
    }

    @Test
    void aFallingBallIsCapturedAtTheBottomRightCornerAndFiredStraightUpAt50() {
        Board board = boardWithAbsorber();
        board.addBall("B", 6, 10, 2, 0);
        tickUntilCaptured(board, "B");
        BallView ball = board.ball("B").orElseThrow();
        assertThat(ball.position()).isEqualTo(new Vect(19.75, 19.75));
        assertThat(ball.velocity()).isEqualTo(Vect.ZERO);
        assertThat(board.gizmo("A").orElseThrow().lastTriggeredAt()).isFinite();
        assertThat(board.energy()).as("captured balls carry no energy").isZero();

        board.trigger("A");
        assertThat(ball.isCaptured()).isFalse();
        assertThat(ball.position()).isEqualTo(new Vect(19.75, 18 - 0.25));
        assertThat(ball.velocity()).isEqualTo(new Vect(0, -Board.ABSORBER_LAUNCH_SPEED));

        board.tick(DT);
        double v = -50 * (1 - Board.DEFAULT_MU * DT - Board.DEFAULT_MU2 * 50 * DT) + Board.DEFAULT_GRAVITY * DT;
        assertThat(ball.velocity().y()).isCloseTo(v, within(1e-12));
        assertThat(ball.position().y()).isCloseTo(17.75 + v * DT, within(1e-12));
    }

    /**
     * Without gravity, ball Front sinks into the absorber's top at 1 L/s and is captured after 0.05 s; Back follows it
     * at 2 L/s, 0.06 L behind, so it would have met Front after 0.06 s, where Front no longer is. It goes on at 2 L/s
     * until the absorber takes it too.
     */
    @Test
    void aBallNeverMeetsABallTheAbsorberHasTakenWhereThatBallWas() {
        Board board = boardWithAbsorber();
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addBall("Front", 10, 17.7, 0, 1);
        board.addBall("Back", 10, 17.14, 0, 2);
        for (int i = 0; i < 12; i++) {
            board.tick(DT);
            BallView back = board.ball("Back").orElseThrow();
            if (!back.isCaptured()) {
                assertThat(back.velocity()).as("tick %d", i + 1).isEqualTo(new Vect(0, 2));
            }
        }
        assertThat(board.ball("Front").orElseThrow().isCaptured()).isTrue();
        assertThat(board.ball("Front").orElseThrow().velocity()).isEqualTo(Vect.ZERO);
    }

    @Test
    void anAbsorberFiresOneBallPerTrigger() {
        Board board = boardWithAbsorber();
        board.addBall("B", 5, 19, 0, 0);
        board.addBall("C", 8, 19, 0, 0);
        assertThat(board.balls()).allMatch(BallView::isCaptured);
        board.trigger("A");
        assertThat(board.ball("B").orElseThrow().isCaptured()).isFalse();
        assertThat(board.ball("C").orElseThrow().isCaptured()).isTrue();
        board.trigger("A");   // the launch spot is still taken by B: C stays held
        assertThat(board.ball("C").orElseThrow().isCaptured()).isTrue();
        for (int i = 0; i < 5; i++) {
            board.tick(DT);
        }
        board.trigger("A");
        assertThat(board.ball("C").orElseThrow().isCaptured()).isFalse();
        assertThat(board.ball("C").orElseThrow().velocity()).isEqualTo(new Vect(0, -50));
        board.trigger("A");   // empty: nothing happens
        assertThat(Invariants.violations(board)).isEmpty();
    }

    @Test
    void aSelfConnectedAbsorberFiresAsSoonAsItCaptures() {
        Board board = boardWithAbsorber();
        board.connect(TriggerSource.gizmo("A"), "A");
        board.addBall("B", 6, 15, 0, 0);
        double lowest = 0;
        boolean firedUp = false;
        for (int i = 0; i < 120; i++) {
            board.tick(DT);
            BallView ball = board.ball("B").orElseThrow();
            assertThat(ball.isCaptured()).as("tick %d", i).isFalse();
            lowest = Math.max(lowest, ball.position().y());
            firedUp |= ball.velocity().y() < -45 && ball.position().x() == 19.75;
            assertThat(Invariants.violations(board)).as("tick %d", i).isEmpty();
        }
        assertThat(firedUp).isTrue();
        assertThat(lowest).isLessThanOrEqualTo(18 - 0.25 + 1e-9);
    }

    @Test
    void anAbsorberAtTheTopCannotFireOutOfTheBoard() {
        Board board = new Board();
        board.addAbsorber("A", 0, 0, 5, 1);
        board.addBall("B", 2, 0.5, 0, 0);
        board.trigger("A");
        assertThat(board.ball("B").orElseThrow().isCaptured()).isTrue();
    }

    @Test
    void aHitBumperTriggersTheFlipperConnectedToIt() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SQUARE, "S", 10, 10);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 2, 2);
        board.connect(TriggerSource.gizmo("S"), "F");
        board.addBall("B", 10.5, 8, 0, 0);
        FlipperView flipper = (FlipperView) board.gizmo("F").orElseThrow();
        for (int i = 0; i < 60 && !flipper.isActive(); i++) {
            board.tick(DT);
        }
        assertThat(flipper.isActive()).isTrue();
        assertThat(flipper.lastTriggeredAt()).isEqualTo(board.gizmo("S").orElseThrow().lastTriggeredAt());
    }

    @Test
    void theOuterWallsTriggerWhatIsConnectedToThem() {
        Board board = new Board();
        board.setGravity(0);
        board.addGizmo(GizmoKind.RIGHT_FLIPPER, "F", 2, 2);
        board.connect(TriggerSource.OUTER_WALLS, "F");
        board.addBall("B", 19.5, 10, 30, 0);   // reaches the wall at x = 19.75 after 1/120 s
        board.tick(DT);
        assertThat(((FlipperView) board.gizmo("F").orElseThrow()).isActive()).isTrue();
    }

    @Test
    void keysSwingFlippersUpOnPressAndDownOnReleaseAndFireAbsorbers() {
        Board board = boardWithAbsorber();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 2, 2);
        board.addBall("B", 4, 19, 0, 0);
        board.bindKey(32, KeyEdge.DOWN, "F");
        board.bindKey(32, KeyEdge.UP, "F");
        board.bindKey(10, KeyEdge.DOWN, "A");
        FlipperView flipper = (FlipperView) board.gizmo("F").orElseThrow();
        board.keyDown(32);
        assertThat(flipper.isActive()).isTrue();
        board.keyDown(32);   // auto-repeat: still up
        assertThat(flipper.isActive()).isTrue();
        board.keyUp(32);
        assertThat(flipper.isActive()).isFalse();
        board.keyUp(10);     // only DOWN is bound for the absorber
        assertThat(board.ball("B").orElseThrow().isCaptured()).isTrue();
        board.keyDown(10);
        assertThat(board.ball("B").orElseThrow().isCaptured()).isFalse();
        board.keyDown(99);   // unbound: nothing
    }

    @Test
    void triggeringAFlipperTogglesIt() {
        Board board = new Board();
        board.addGizmo(GizmoKind.RIGHT_FLIPPER, "F", 2, 2);
        FlipperView flipper = (FlipperView) board.gizmo("F").orElseThrow();
        board.trigger("F");
        assertThat(flipper.isActive()).isTrue();
        board.trigger("F");
        assertThat(flipper.isActive()).isFalse();
        assertThatThrownBy(() -> board.trigger("Nope")).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("Nope");
    }

    /** 90 degrees at 1080 deg/s = 6 pi rad/s: (pi/2) / (6 pi) = 1/12 s, exactly 5 ticks of 1/60 s. */
    @Test
    void aFlipperReachesNinetyDegreesAfterExactlyATwelfthOfASecondAndStops() {
        Board board = new Board();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 4, 6);
        FlipperView flipper = (FlipperView) board.gizmo("F").orElseThrow();
        board.keyDown(1);   // unbound
        board.trigger("F");
        for (int i = 1; i <= 4; i++) {
            board.tick(DT);
            assertThat(flipper.angleFromRest()).isCloseTo(18.0 * i, within(1e-9));
            assertThat(flipper.isMoving()).isTrue();
        }
        board.tick(DT);
        assertThat(flipper.angleFromRest()).isEqualTo(90.0);
        assertThat(flipper.isMoving()).isFalse();
        assertThat(flipper.tip().x()).isCloseTo(4 + 1.75, within(1e-12));
        assertThat(flipper.tip().y()).isCloseTo(6 + 0.25, within(1e-12));
        board.tick(DT);
        assertThat(flipper.angleFromRest()).isEqualTo(90.0);

        board.trigger("F");
        board.tick(0.05);   // 54 degrees back
        assertThat(flipper.angleFromRest()).isCloseTo(36, within(1e-9));
        board.tick(0.05);   // would be 108: stops exactly at rest
        assertThat(flipper.angleFromRest()).isZero();
        assertThat(flipper.tip()).isEqualTo(new Vect(4.25, 7.75));
    }

    @Test
    void aRightFlipperSwingsTheMirrorWay() {
        Board board = new Board();
        board.addGizmo(GizmoKind.RIGHT_FLIPPER, "F", 4, 6);
        FlipperView flipper = (FlipperView) board.gizmo("F").orElseThrow();
        board.trigger("F");
        board.tick(DT * 2.5);   // 45 degrees: the tip is 1.5 L from the pivot, down and to the left
        Vect offset = flipper.tip().minus(flipper.pivot());
        assertThat(offset.x()).isCloseTo(-1.5 * Math.sqrt(0.5), within(1e-12));
        assertThat(offset.y()).isCloseTo(1.5 * Math.sqrt(0.5), within(1e-12));
        board.tick(DT * 2.5);
        assertThat(flipper.tip().x()).isCloseTo(4.25, within(1e-12));
        assertThat(flipper.tip().y()).isCloseTo(6.25, within(1e-12));
    }

    /**
     * An absorber along the top, connected to itself, fires into a ball wedged against the top wall right above its
     * mouth: the fired ball comes straight back and is captured at that same moment. The absorber fires at most
     * once a tick, so the ball stays held instead of being fired again and again at no time apart (the fuzz of
     * issue 20 found 470 such captures a tick, every tick); the next tick may fire it again.
     */
    @Test
    void anAbsorberFiresAtMostOnceATick() {
        Board board = new Board();
        board.setGravity(0);
        board.addAbsorber("A", 14, 1, 18, 3);
        board.connect(TriggerSource.gizmo("A"), "A");
        board.addBall("W", 17.75, Board.BALL_RADIUS, 0, 0);
        board.addBall("B", 16, 2, 0, 0);   // inside the absorber: captured at once
        assertThat(board.ball("B").orElseThrow().isCaptured()).isTrue();
        board.trigger("A");
        board.tick(DT);
        assertThat(board.ball("B").orElseThrow().isCaptured()).as("came back and stays held").isTrue();
        assertThat(board.lastTick().collisions()).isLessThan(10);
        assertThat(board.guardsFired().wedged() + board.guardsFired().collisionCap()).isZero();
        board.delete("W");
        board.trigger("A");
        assertThat(board.ball("B").orElseThrow().isCaptured()).as("the next tick fires it again").isFalse();
    }
}
