package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gizmoball.model.Board;
import gizmoball.model.game.GameRules;
import gizmoball.model.game.Nudge;
import gizmoball.model.game.Tilt;
import gizmoball.model.game.Points;
import gizmoball.model.gizmo.GizmoKind;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/**
 * The game's lines, our additions to the standard format (docs/board-files.md): each is written {@code #@Word}, so a
 * loader that knows only the standard format skips it as a comment and loads the rest; ours reads it back.
 */
class GameLinesTest {
    private static final String GAME = """
            Circle C 5 5
            Square S 8 8
            Absorber A 0 19 20 20
            Absorber Side 19 10 20 12
            Ball B 19.75 19.75 0.0 0.0
            Gravity 25.0
            Friction 0.025 0.025
            #@Balls 5
            #@ExtraBall 1000
            #@Nudge 3.0 65 68 87
            #@Tilt 3 4.0
            #@BallSave 6.0
            #@Drain A
            #@Drain Side
            #@Points C 250
            #@Points S -5
            """;

    @Test
    void aGameIsWrittenInCanonicalOrderAfterTheStandardLinesAndReadBackEqual() throws BoardFileException {
        Board board = BoardFiles.load("game", GAME);

        assertThat(board.gameRules()).isEqualTo(new GameRules(5, Set.of("A", "Side"), Map.of("C", 250, "S", -5),
                OptionalLong.of(1000), Optional.of(new Nudge(3, 65, 68, 87)), new Tilt(3, 4), 6));
        assertThat(BoardFiles.toText(board)).isEqualTo(GAME);
        assertThat(BoardContents.of(BoardFiles.load("again", BoardFiles.toText(board))))
                .isEqualTo(BoardContents.of(board));
    }

    @Test
    void aLoaderOfTheStandardFormatSkipsTheGameLinesAndLoadsTheRest() throws BoardFileException {
        String standardOnly = Arrays.stream(GAME.split("\n")).filter(line -> !line.startsWith("#"))
                .collect(Collectors.joining("\n", "", "\n"));

        Board board = BoardFiles.load("standard", standardOnly);

        assertThat(board.gizmos()).hasSize(4);
        assertThat(board.gameRules()).isEqualTo(GameRules.DEFAULT);
        assertThat(BoardFiles.toText(board)).isEqualTo(standardOnly).doesNotContain("#@");
    }

    @Test
    void aValueEqualToTheKindsIsNoValueOfItsOwnAndASandboxWritesNoGameLine() throws BoardFileException {
        Board board = BoardFiles.load("defaults", "Circle C 5 5\n#@Points C " + Points.defaultFor(GizmoKind.CIRCLE)
                + "\n#@Balls 3\n");

        assertThat(board.gameRules()).isEqualTo(GameRules.DEFAULT);
        assertThat(BoardFiles.toText(board)).doesNotContain("#@");
    }

    @Test
    void balls() throws BoardFileException {
        assertThat(BoardFiles.toText(BoardFiles.load("balls", "#@Balls 1\n"))).endsWith("\n#@Balls 1\n");
    }

    @Test
    void aGameLineBeforeTheGizmoItNamesWaitsForIt() throws BoardFileException {
        LoadResult result = BoardFiles.loadSkippingBadLines("forward", "#@Drain A\n#@Points A 7\nAbsorber A 0 19 20 20\n");

        assertThat(result.skippedLines()).isEmpty();
        assertThat(result.board().gameRules().drains()).containsExactly("A");
        assertThat(result.board().gameRules().ownPoints()).containsEntry("A", 7);
        assertThat(result.notes()).extracting(BoardFileNote::line).containsExactly(1, 2);
    }

    @Test
    void ourStandardCommandsAreReadWithTheMarkToo() throws BoardFileException {
        Board board = BoardFiles.load("marked", "Triangle T 1 1\n#@Rotate T\n");

        assertThat(board.gizmo("T").orElseThrow().rotation()).isEqualTo(1);
    }

    @Test
    void aGameLineWithoutTheMarkIsRefusedSayingHowToWriteIt() {
        assertThatThrownBy(() -> BoardFiles.load("bare.txt", "Absorber A 0 19 20 20\nDrain A\n"))
                .isInstanceOf(BoardFileException.class)
                .hasMessageContaining("bare.txt:2:")
                .hasMessageContaining("Drain is an addition of this game to the format: it is written #@Drain");
    }

    @Test
    void anUnknownMarkedWordIsAnErrorOfItsLineAndAMarkFollowedBySpaceIsAComment() throws BoardFileException {
        assertThatThrownBy(() -> BoardFiles.load("typo.txt", "Absorber A 0 19 20 20\n#@Drian A\n"))
                .isInstanceOf(BoardFileException.class)
                .hasMessageContaining("typo.txt:2:").hasMessageContaining("unknown command '#@Drian'")
                .hasMessageContaining("#@Drain");
        assertThat(BoardFiles.load("comment", "#@ Drain A\n").gameRules()).isEqualTo(GameRules.DEFAULT);
    }

    @Test
    void refusalsNameTheLineAndTheReason() {
        List<BoardFileError> errors = BoardFiles.loadSkippingBadLines("bad.txt", """
                Square S 1 1
                #@Drain S
                #@Drain Nowhere
                #@Balls 0
                #@Balls 2.5
                #@Points S 2000000
                #@ExtraBall 0
                #@Nudge 30
                #@Nudge 4 37 37 38
                #@Tilt 1 5
                #@Tilt 4 0
                #@BallSave 31
                #@Nudge
                KeyConnect key 37 down S
                """).skippedLines();

        assertThat(errors).extracting(BoardFileError::line).containsExactly(2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 14);
        assertThat(errors.get(0).reason()).contains("only an absorber can be a drain: S is a square");
        assertThat(errors.get(1).reason()).contains("no gizmo named Nowhere");
        assertThat(errors.get(2).reason()).contains("a game has 1 to 99 balls, not 0");
        assertThat(errors.get(3).reason()).contains("is not a whole number");
        assertThat(errors.get(4).reason()).contains("points of S must lie within");
        assertThat(errors.get(5).reason()).contains("an extra ball is awarded at a score of 1 or more");
        assertThat(errors.get(6).reason()).contains("a nudge adds more than 0 and at most 20 L/s, not 30");
        assertThat(errors.get(7).reason()).contains("three different keys");
        assertThat(errors.get(8).reason()).contains("a tilt comes with the 2nd to 20th nudge, not the 1th");
        assertThat(errors.get(9).reason()).contains("at most 60 seconds, not 0");
        assertThat(errors.get(10).reason()).contains("a ball save lasts 0 (none) to 30 seconds, not 31");
        assertThat(errors.get(11).reason()).contains("key 37 nudges the board: it drives nothing else");
    }

    /** The author's file stays as written where the game did not change: comments, order, the other game lines. */
    @Test
    void savingAnEditedGameOverItsFileRewritesOnlyTheChangedGameLines() throws Exception {
        String authored = "# my table\n" + GAME.replace("#@Drain A\n", "# the drain\n#@Drain A\n");
        LoadResult loaded = BoardFiles.loadSkippingBadLines("mine.txt", authored);
        Board board = loaded.board();

        board.setPoints("C", 300);
        board.setBallsPerGame(4);
        String saved = loaded.authored().saving(board).text();

        assertThat(saved).startsWith("# my table\n").contains("# the drain\n#@Drain A\n", "#@Points C 300\n",
                "#@Balls 4\n", "#@Points S -5\n", "#@ExtraBall 1000\n").doesNotContain("#@Points C 250", "#@Balls 5");
        assertThat(BoardContents.of(BoardFiles.load("saved", saved))).isEqualTo(BoardContents.of(board));
    }

    @Test
    void deletingAGizmoForgetsItsGameLines() throws BoardFileException {
        Board board = BoardFiles.load("game", GAME);

        board.delete("A");
        board.delete("C");

        assertThat(board.gameRules().drains()).containsExactly("Side");
        assertThat(board.gameRules().ownPoints()).containsOnlyKeys("S");
    }
}
