package gizmoball.model.game;

import static gizmoball.model.game.LauncherBoards.DT;
import static gizmoball.model.game.LauncherBoards.SPACE;
import static gizmoball.model.game.LauncherBoards.launcherUnderASquare;
import static gizmoball.model.game.LauncherBoards.ticks;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import physics.Vect;

/** Nudges push every free ball by the nudge's speed; the tilt's count of them within its seconds tilts the game. */
class NudgeAndTiltTest {
    private static final int LEFT = 37;
    private static final int RIGHT = 39;
    private static final int UP = 38;

    private static void nudge(Board board, int key) {
        board.keyDown(key);
        board.keyUp(key);
    }

    @Test
    void aNudgeAddsExactlyItsSpeedToEveryFreeBallWakesSleepersAndLeavesHeldBallsBe() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SQUARE, "Floor", 4, 10);
        board.addAbsorber("A", 0, 19, 20, 20);
        board.addBall("Held", 19.75, 19.75, 0, 0);
        board.addBall("Resting", 4.5, 10 - Board.BALL_RADIUS, 0, 0);
        for (int i = 0; i < 600 && !board.ball("Resting").orElseThrow().isAsleep(); i++) {
            board.tick(DT);
        }
        assertThat(board.ball("Resting").orElseThrow().isAsleep()).as("asleep on the square").isTrue();
        board.addBall("Flying", 12, 5, 3.25, -7.5);
        board.setNudge(Optional.of(new Nudge(2.5, LEFT, RIGHT, UP)));
        Vect resting = board.ball("Resting").orElseThrow().velocity();

        nudge(board, LEFT);
        assertThat(board.ball("Flying").orElseThrow().velocity()).isEqualTo(new Vect(3.25 - 2.5, -7.5));
        assertThat(board.ball("Resting").orElseThrow().velocity()).isEqualTo(resting.plus(new Vect(-2.5, 0)));
        assertThat(board.ball("Resting").orElseThrow().isAsleep()).as("woken").isFalse();
        assertThat(board.ball("Held").orElseThrow().velocity()).isEqualTo(Vect.ZERO);
        assertThat(board.ball("Held").orElseThrow().isCaptured()).isTrue();

        nudge(board, UP);
        nudge(board, RIGHT);
        assertThat(board.ball("Flying").orElseThrow().velocity()).isEqualTo(new Vect(3.25 - 2.5 + 2.5, -7.5 - 2.5));
        assertThat(board.game().keys()).hasSize(6);
    }

    /** A game with a nudge and a flipper on Z: nudges spaced {@code gap} ticks apart. */
    private static Board nudgeable(Tilt tilt) {
        Board board = launcherUnderASquare(2);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 5, 10);
        board.bindKey(90, KeyEdge.DOWN, "LF");
        board.bindKey(90, KeyEdge.UP, "LF");
        board.setNudge(Optional.of(Nudge.DEFAULT));
        board.setTilt(tilt);
        board.keyDown(SPACE);   // the ball in play: a tilt lasts while it is free
        board.keyUp(SPACE);
        ticks(board, 1);
        return board;
    }

    @Test
    void nNudgesWithinTheSecondsTiltNMinusOneOnlyWarn() {
        Tilt tilt = new Tilt(4, 1);
        Board warned = nudgeable(tilt);
        for (int i = 0; i < 3; i++) {
            nudge(warned, LEFT);
            ticks(warned, 10);
        }
        assertThat(warned.game().isTilted()).isFalse();
        assertThat(warned.game().notices()).extracting(Notice::kind).containsExactly(Notice.Kind.WARNING);

        Board tilted = nudgeable(tilt);
        for (int i = 0; i < 4; i++) {
            nudge(tilted, LEFT);
            ticks(tilted, 10);
        }
        assertThat(tilted.game().isTilted()).isTrue();
        assertThat(tilted.game().notices()).extracting(Notice::kind)
                .containsExactly(Notice.Kind.WARNING, Notice.Kind.TILT);
    }

    @Test
    void nudgesSpreadWiderThanTheSecondsNeverTilt() {
        Board board = nudgeable(new Tilt(3, 1));
        for (int i = 0; i < 8; i++) {
            nudge(board, RIGHT);
            ticks(board, 31);   // 0.52 s apart: never three within a second
        }
        assertThat(board.game().isTilted()).isFalse();
    }

    @Test
    void aTiltKillsTheFlippersAndTheScoreUntilTheBallDrains() {
        Board board = nudgeable(new Tilt(2, 5));
        board.keyDown(90);
        ticks(board, 3);
        assertThat(((FlipperView) board.gizmo("LF").orElseThrow()).isActive()).isTrue();

        nudge(board, UP);
        nudge(board, UP);
        assertThat(board.game().isTilted()).isTrue();
        assertThat(((FlipperView) board.gizmo("LF").orElseThrow()).isActive()).as("lowered").isFalse();
        board.keyUp(90);
        board.keyDown(90);
        assertThat(((FlipperView) board.gizmo("LF").orElseThrow()).isActive()).as("dead").isFalse();

        int drains = board.game().drains().size();
        while (board.game().drains().size() == drains) {
            board.tick(DT);
        }
        assertThat(board.game().score()).as("the square's hit scored nothing").isZero();
        assertThat(board.game().isTilted()).as("over with the ball").isFalse();
        assertThat(board.game().ballsLeft()).isEqualTo(1);
        BallView ball = board.balls().get(0);
        assertThat(ball.isCaptured()).isTrue();
    }
}
