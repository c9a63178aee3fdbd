package gizmoball.model;

import gizmoball.model.gizmo.Setting;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gizmoball.model.gizmo.AbsorberView;
import gizmoball.model.gizmo.Plunger;
import gizmoball.model.loop.BallView;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import physics.Vect;

/**
 * A plunger: its key pulls it while held, the release fires at v(t) = 10 + (full - 10) min(t, T) / T, t the board
 * time the key was held. Ticks of 1/64 s add up exactly, so the speeds are the closed form to the bit.
 */
class PlungerTest {
    private static final double DT = 1.0 / 64;
    private static final int SPACE = 32;

    /** A plunger lane's absorber at the bottom right, holding ball B, fired by space. */
    private static Board plungerBoard(Plunger plunger) {
        Board board = new Board();
        board.addAbsorber("P", 19, 19, 20, 20);
        board.set("P", new Setting.Pull(Optional.of(plunger)));
        board.bindKey(SPACE, KeyEdge.DOWN, "P");
        board.addBall("B", 19.5, 19.5, 0, 0);
        return board;
    }

    private static BallView holdFor(Board board, int ticks) {
        board.keyDown(SPACE);
        for (int i = 0; i < ticks; i++) {
            board.tick(DT);
        }
        assertThat(board.ball("B").orElseThrow().isCaptured()).as("held while the key is down").isTrue();
        board.keyUp(SPACE);
        return board.ball("B").orElseThrow();
    }

    @Test
    void aHoldOfKnownLengthLaunchesAtItsClosedFormSpeed() {
        Plunger plunger = new Plunger(60, 1.0);
        for (int ticks : new int[] {0, 1, 16, 32, 48, 64, 100}) {
            Board board = plungerBoard(plunger);
            BallView ball = holdFor(board, ticks);
            double t = ticks / 64.0;
            double expected = 10 + (60 - 10) * Math.min(t, 1.0) / 1.0;
            assertThat(ball.isCaptured()).isFalse();
            assertThat(ball.velocity()).as("after %d ticks held", ticks).isEqualTo(new Vect(0, -expected));
            assertThat(ball.position()).isEqualTo(new Vect(19.75, 19 - Board.BALL_RADIUS));
        }
    }

    @Test
    void theViewSeesHowFarItIsPulled() {
        Board board = plungerBoard(new Plunger(60, 2.0));
        AbsorberView view = (AbsorberView) board.gizmo("P").orElseThrow();
        assertThat(view.pull()).isZero();
        board.keyDown(SPACE);
        for (int i = 0; i < 32; i++) {
            board.tick(DT);
        }
        assertThat(((AbsorberView) board.gizmo("P").orElseThrow()).pull()).isEqualTo(0.25);
        board.keyUp(SPACE);
        assertThat(((AbsorberView) board.gizmo("P").orElseThrow()).pull()).isZero();
    }

    @Test
    void aStandardAbsorberStillFiresAtOnceAt50() {
        Board board = plungerBoard(Plunger.DEFAULT);
        board.set("P", new Setting.Pull(Optional.empty()));
        board.keyDown(SPACE);
        assertThat(board.ball("B").orElseThrow().velocity()).isEqualTo(new Vect(0, -Board.ABSORBER_LAUNCH_SPEED));
    }

    @Test
    void aTriggerFiresAPlungerAtOnceAtItsFullPull() {
        Board board = plungerBoard(new Plunger(70, 1.0));
        board.trigger("P");
        assertThat(board.ball("B").orElseThrow().velocity()).isEqualTo(new Vect(0, -70));
    }

    @Test
    void aCopyOfTheBoardGoesOnWithThePull() {
        Board board = plungerBoard(new Plunger(60, 1.0));
        board.keyDown(SPACE);
        for (int i = 0; i < 16; i++) {
            board.tick(DT);
        }
        Board copy = board.copy();
        for (int i = 0; i < 16; i++) {
            copy.tick(DT);
        }
        copy.keyUp(SPACE);
        assertThat(copy.ball("B").orElseThrow().velocity()).isEqualTo(new Vect(0, -(10 + 50 * 0.5)));
    }

    @Test
    void outOfRangeSettingsAreRefusedAndOnlyAbsorbersArePlungers() {
        Board board = plungerBoard(Plunger.DEFAULT);
        assertThatThrownBy(() -> board.set("P", new Setting.Pull(Optional.of(new Plunger(10, 1)))))
                .isInstanceOf(BoardEditException.class).hasMessageContaining("faster than 10");
        assertThatThrownBy(() -> board.set("P", new Setting.Pull(Optional.of(new Plunger(201, 1)))))
                .isInstanceOf(BoardEditException.class).hasMessageContaining("at most 200");
        assertThatThrownBy(() -> board.set("P", new Setting.Pull(Optional.of(new Plunger(50, 6)))))
                .isInstanceOf(BoardEditException.class).hasMessageContaining("0.1 to 5 seconds");
        board.addGizmo(gizmoball.model.gizmo.GizmoKind.CIRCLE, "C", 5, 5);
        assertThatThrownBy(() -> board.set("C", new Setting.Pull(Optional.of(Plunger.DEFAULT))))
                .isInstanceOf(BoardEditException.class).hasMessageContaining("only an absorber");
        assertThat(((AbsorberView) board.gizmo("P").orElseThrow()).plunger()).contains(Plunger.DEFAULT);
    }
}
