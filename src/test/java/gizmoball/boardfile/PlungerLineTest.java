package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.gizmo.AbsorberView;
import gizmoball.model.gizmo.Plunger;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** {@code #@Plunger <absorber> [<full-speed> [<pull-seconds>]]}: read with its defaults, written in full, refused with reasons. */
class PlungerLineTest {
    private static final String LANE = "Absorber P 19 19 20 20\nKeyConnect key 32 down P\n";

    private static Optional<Plunger> plungerOf(Board board) {
        return ((AbsorberView) board.gizmo("P").orElseThrow()).plunger();
    }

    @Test
    void theSpeedAndTimeAreOptionalAndTheLineIsWrittenInFull() throws BoardFileException {
        assertThat(plungerOf(BoardFiles.load("bare", LANE + "#@Plunger P\n"))).contains(Plunger.DEFAULT);
        assertThat(plungerOf(BoardFiles.load("speed", LANE + "#@Plunger P 60\n"))).contains(new Plunger(60, 1));
        Board board = BoardFiles.load("full", LANE + "#@Plunger P 60 1.5\n");
        assertThat(plungerOf(board)).contains(new Plunger(60, 1.5));
        assertThat(BoardFiles.toText(board)).contains("\n#@Plunger P 60.0 1.5\n");
        assertThat(BoardContents.of(BoardFiles.load("again", BoardFiles.toText(board))))
                .isEqualTo(BoardContents.of(board));
    }

    @Test
    void aStandardAbsorberWritesNoPlungerLine() throws BoardFileException {
        Board board = BoardFiles.load("standard", LANE);
        assertThat(plungerOf(board)).isEmpty();
        assertThat(BoardFiles.toText(board)).doesNotContain("#@");
    }

    @Test
    void refusalsNameTheLineAndTheReason() {
        List<BoardFileError> errors = BoardFiles.loadSkippingBadLines("bad.txt", LANE + """
                Square S 1 1
                #@Plunger S
                #@Plunger P 5
                #@Plunger P 60 9
                #@Plunger P fast
                #@Plunger P 60 1 2
                """).skippedLines();

        assertThat(errors).extracting(BoardFileError::line).containsExactly(4, 5, 6, 7, 8);
        assertThat(errors.get(0).reason()).contains("only an absorber can be a plunger: S is a square");
        assertThat(errors.get(1).reason()).contains("faster than 10 L/s and at most 200 L/s, not 5");
        assertThat(errors.get(2).reason()).contains("0.1 to 5 seconds, not 9");
        assertThat(errors.get(3).reason()).contains("fast");
        assertThat(errors.get(4).reason()).contains("wrong number of arguments");
    }
}
