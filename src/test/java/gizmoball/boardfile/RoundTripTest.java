package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** Save then load gives an equal board, bit for bit in every number. */
class RoundTripTest {
    private static final long SEED = 4_170_2026L;
    private static final int BOARDS = 200;

    @Test
    void randomBoardsSurviveSaveAndLoad() throws BoardFileException {
        RandomBoards boards = new RandomBoards(new Random(SEED));
        for (int i = 0; i < BOARDS; i++) {
            Board board = boards.next();
            assertRoundTrips(board, "seed " + SEED + " board " + i);
        }
    }

    @Test
    void boardsInPlaySurviveSaveAndLoad() throws BoardFileException {
        // After some ticks balls sit at arbitrary doubles, some in absorbers, some touching gizmos.
        RandomBoards boards = new RandomBoards(new Random(SEED + 1));
        for (int i = 0; i < 40; i++) {
            Board board = boards.next();
            for (int tick = 0; tick < 30; tick++) {
                board.tick(Board.DEFAULT_TICK);
            }
            assertRoundTrips(board, "seed " + (SEED + 1) + " board " + i + " after 30 ticks");
        }
    }

    private static void assertRoundTrips(Board board, String description) throws BoardFileException {
        String text = BoardFiles.toText(board);
        Board reloaded = BoardFiles.load(description, text);
        assertThat(BoardContents.of(board).differences(BoardContents.of(reloaded))).as("%s:%n%s", description, text)
                .isEmpty();
        assertThat(BoardFiles.toText(reloaded)).as(description).isEqualTo(text);
    }
}
