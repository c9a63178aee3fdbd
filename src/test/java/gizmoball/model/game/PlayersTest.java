package gizmoball.model.game;

import static gizmoball.model.game.LauncherBoards.launchAndWait;
import static gizmoball.model.game.LauncherBoards.launcherUnderASquare;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gizmoball.model.Board;
import org.junit.jupiter.api.Test;

/** 1 to 4 players taking turns ball by ball, each with a score of their own. */
class PlayersTest {

    @Test
    void turnsAlternatePerDrainedBallEachScoreIsItsOwnAndTheGameEndsAfterEveryPlayersLastBall() {
        Board board = launcherUnderASquare(2);
        board.setPlayers(2);
        assertThat(board.game().players()).isEqualTo(2);
        assertThat(board.game().ballsLeft()).isEqualTo(4);

        int[] expectedPlayer = {0, 1, 0, 1};
        long[][] expectedScores = {{125, 0}, {125, 125}, {250, 125}, {250, 250}};
        for (int ball = 0; ball < 4; ball++) {
            assertThat(board.game().currentPlayer()).as("ball %d", ball).isEqualTo(expectedPlayer[ball]);
            assertThat(board.game().isOver()).isFalse();
            launchAndWait(board);
            assertThat(board.game().score(0)).isEqualTo(expectedScores[ball][0]);
            assertThat(board.game().score(1)).isEqualTo(expectedScores[ball][1]);
            assertThat(board.game().ballsLeft()).isEqualTo(3 - ball);
        }
        assertThat(board.game().isOver()).isTrue();
        assertThat(board.game().score()).isEqualTo(500);
        assertThat(board.game().notices()).extracting(Notice::kind, Notice::player).containsExactly(
                org.assertj.core.groups.Tuple.tuple(Notice.Kind.NEXT_PLAYER, 1),
                org.assertj.core.groups.Tuple.tuple(Notice.Kind.NEXT_PLAYER, 0),
                org.assertj.core.groups.Tuple.tuple(Notice.Kind.NEXT_PLAYER, 1));
    }

    @Test
    void anExtraBallIsItsPlayersAndTheOthersGoOnWithout() {
        Board board = launcherUnderASquare(1);
        board.setExtraBallAt(java.util.OptionalLong.of(125));
        board.setPlayers(3);

        int launches = 0;
        while (!board.game().isOver()) {
            launchAndWait(board);
            launches++;
            assertThat(launches).isLessThanOrEqualTo(6);
        }
        // Each reaches 125 with their first ball and earns one more: two balls each.
        assertThat(launches).isEqualTo(6);
        assertThat(new long[] {board.game().score(0), board.game().score(1), board.game().score(2)})
                .containsExactly(250, 250, 250);
    }

    @Test
    void thePlayersAreChosenBeforeTheFirstTickAndACopyOrResetKeepsThem() {
        Board board = launcherUnderASquare(1);
        assertThatThrownBy(() -> board.setPlayers(5)).isInstanceOf(IllegalArgumentException.class);
        board.setPlayers(4);
        Board copy = board.copy();
        assertThat(copy.game().players()).isEqualTo(4);
        LauncherBoards.ticks(board, 1);
        assertThatThrownBy(() -> board.setPlayers(2)).isInstanceOf(IllegalStateException.class);
        board.clear();
        assertThat(board.game().players()).isEqualTo(4);
    }
}
