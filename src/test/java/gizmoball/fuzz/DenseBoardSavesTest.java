package gizmoball.fuzz;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardFileException;
import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;

import java.util.List;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Every file the game writes loads again: dense boards (issue 20's fuzz), played with their key scripts and saved
 * every 250 ticks, load again strictly with every ball where it was. Balls resting on the floor, on each other and
 * in packed pockets lie against the walls and each other to rounding, beyond the exact limits by some 1e-14 L.
 */
class DenseBoardSavesTest {
    private static final int TICKS = 2_500;
    private static final int EVERY = 250;

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {3, 8, 17, 25, 34, 40, 58, 71, 100, 109, 515, 622})
    void aDenseBoardSavedDuringPlayLoadsAgainWithItsBallsWhereTheyWere(long seed) throws BoardFileException {
        FuzzCase fuzzCase = DenseBoards.generate(seed, TICKS);
        Board board = fuzzCase.board();
        KeyScript.Player keys = fuzzCase.keys().player();
        for (int tick = 1; tick <= TICKS; tick++) {
            keys.beforeTick(board, tick);
            board.tick(Reproduction.DT);
            if (tick % EVERY == 0) {
                Board reloaded = BoardFiles.load("seed " + seed + " at tick " + tick, BoardFiles.toText(board));
                assertThat(places(reloaded)).as("seed %d, tick %d", seed, tick).isEqualTo(places(board));
            }
        }
    }

    private static List<String> places(Board board) {
        return board.balls().stream().map(b -> b.name() + " " + b.position() + " " + b.velocity()).toList();
    }
}
