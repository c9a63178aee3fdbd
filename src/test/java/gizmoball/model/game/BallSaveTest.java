package gizmoball.model.game;

import static gizmoball.model.game.LauncherBoards.launchAndWait;
import static gizmoball.model.game.LauncherBoards.launcherUnderASquare;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import org.junit.jupiter.api.Test;

/** The ball save: a ball drained within its seconds after the launch is given back, once a ball. */
class BallSaveTest {

    @Test
    void aBallDrainedInsideTheSaveReturnsOnceAndASecondDrainInsideTheWindowIsLost() {
        Board board = launcherUnderASquare(2);
        board.setBallSave(5);

        launchAndWait(board);   // 0.62 s after its launch: saved
        assertThat(board.game().ballsLeft()).isEqualTo(2);
        assertThat(board.game().notices()).extracting(Notice::kind).containsExactly(Notice.Kind.BALL_SAVED);
        assertThat(board.balls()).hasSize(1);
        assertThat(board.balls().get(0).isCaptured()).as("back in the launcher").isTrue();

        launchAndWait(board);   // again 0.62 s after its launch, but saved once already: lost
        assertThat(board.game().ballsLeft()).isEqualTo(1);
        assertThat(board.game().notices()).extracting(Notice::kind).containsExactly(Notice.Kind.BALL_SAVED);

        launchAndWait(board);   // the next ball has a save of its own
        assertThat(board.game().ballsLeft()).isEqualTo(1);
        assertThat(board.game().notices()).extracting(Notice::kind)
                .containsExactly(Notice.Kind.BALL_SAVED, Notice.Kind.BALL_SAVED);
        assertThat(board.game().score()).isEqualTo(3 * 125);
    }

    @Test
    void aDrainAfterTheSaveIsOverIsLostAndNoSaveIsTheDefault() {
        Board late = launcherUnderASquare(2);
        late.setBallSave(0.5);   // the ball is back after 0.62 s
        launchAndWait(late);
        assertThat(late.game().ballsLeft()).isEqualTo(1);

        Board none = launcherUnderASquare(2);
        assertThat(none.gameRules().ballSaveSeconds()).isZero();
        launchAndWait(none);
        assertThat(none.game().ballsLeft()).isEqualTo(1);
        assertThat(none.game().notices()).isEmpty();
    }
}
