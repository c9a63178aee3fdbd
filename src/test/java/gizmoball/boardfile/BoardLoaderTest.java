package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;
import static org.assertj.core.groups.Tuple.tuple;

import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class BoardLoaderTest {

    @Test
    void toleratesWhatRealFilesContain() throws BoardFileException {
        String text = "# written by another implementation\r\n"
                + "\r\n"
                + "  sQuArE   9lives   7.0 \t 3 \r\n"
                + "TRIANGLE t-1/x 19 0\r\n"
                + "rotate t-1/x\r\n"
                + "leftflipper LF 0.0 17.0\r\n"
                + "absorber A 0 19 20 20\r\n"
                + "ball B 10.5 2.5 1.0 -2.0\r\n"
                + "connect A A\r\n"
                + "connect 9lives LF\r\n"
                + "keyconnect KEY 76.0 DOWN LF\r\n"
                + "KeyConnect key 32 Up A";
        Board board = BoardFiles.load("quirks", text);

        assertThat(board.gizmos()).extracting(g -> g.name() + " " + g.kind() + " " + g.x() + " " + g.y()
                + " r" + g.rotation()).containsExactly("9lives SQUARE 7 3 r0", "t-1/x TRIANGLE 19 0 r1",
                "LF LEFT_FLIPPER 0 17 r0", "A ABSORBER 0 19 r0");
        assertThat(board.gizmo("A").orElseThrow().width()).isEqualTo(20);
        assertThat(board.balls()).singleElement().satisfies(ball -> {
            assertThat(ball.position().x()).isEqualTo(10.5);
            assertThat(ball.velocity().y()).isEqualTo(-2.0);
        });
        assertThat(board.connections()).containsExactly(new Connection(TriggerSource.gizmo("A"), "A"),
                new Connection(TriggerSource.gizmo("9lives"), "LF"));
        assertThat(board.keyBindings()).containsExactly(new KeyBinding(76, KeyEdge.DOWN, "LF"),
                new KeyBinding(32, KeyEdge.UP, "A"));
        assertThat(board.gravity()).isEqualTo(Board.DEFAULT_GRAVITY);
        assertThat(board.mu()).isEqualTo(Board.DEFAULT_MU);
        assertThat(board.mu2()).isEqualTo(Board.DEFAULT_MU2);
    }

    @Test
    void readsLaterCommandsOnTopOfEarlierOnes() throws BoardFileException {
        Board board = BoardFiles.load("edits", String.join("\n",
                "Square S 1 1", "Circle C 2 2", "Ball B 5.5 5.5 0 0", "Move S 3 4", "Move B 6.25 7.5",
                "Delete C", "Gravity 10", "Friction 0.5 0.25", "Gravity 12.5"));
        assertThat(board.gizmos()).singleElement().satisfies(s -> assertThat(List.of(s.x(), s.y())).containsExactly(3, 4));
        assertThat(board.ball("B").orElseThrow().position().x()).isEqualTo(6.25);
        assertThat(board.gravity()).isEqualTo(12.5);
        assertThat(List.of(board.mu(), board.mu2())).containsExactly(0.5, 0.25);
    }

    /** One board refusal per row: the line refused, and what the reason the model gives must say. */
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
            "outside the board (cell)       | Square S 20 3                 | outside",
            "outside the board (footprint)  | LeftFlipper F 19 5            | outside",
            "outside the board (absorber)   | Absorber A 0 19 21 20         | outside",
            "outside the board (ball)       | Ball B 20.1 3 0 0             | outside",
            "overlap                        | Square T 1 1                  | overlap gizmo S1",
            "overlap with a flipper box     | Circle T 2 3                  | overlap gizmo F1",
            "ball overlapping a gizmo       | Ball B 1.5 1.5 0 0            | overlap gizmo S1",
            "duplicate name                 | Circle S1 5 5                 | S1 is already used",
            "duplicate name, ball and gizmo | Ball S1 5.5 5.5 0 0           | S1 is already used",
            "reserved name                  | Square OuterWalls 5 5         | reserved",
            "unknown name in Connect        | Connect S1 Nobody             | no gizmo named Nobody",
            "unknown source in Connect      | Connect Nobody S1             | no gizmo named Nobody",
            "unknown name in KeyConnect     | KeyConnect key 32 down Nobody | no gizmo named Nobody",
            "unknown name in Rotate         | Rotate Nobody                 | no gizmo named Nobody",
            "unknown name in Delete         | Delete Nobody                 | no gizmo or ball named Nobody",
            "unknown name in Move           | Move Nobody 3 3               | no gizmo or ball named Nobody",
            "gizmo moved off the grid       | Move S1 3.5 3                 | gizmo S1 can only move to a whole cell",
            "gizmo moved onto another       | Move S1 2 3                   | overlap gizmo F1",
            "empty absorber                 | Absorber A 3 3 3 4            | at least one cell",
            "same connection twice          | Connect S1 F1                 | already exists",
            "negative friction              | Friction -0.1 0.025           | negative"})
    void eachBoardRefusalBecomesAnErrorOnItsLine(String why, String line, String reasonSays) {
        String text = "Square S1 1 1\nLeftFlipper F1 2 3\nConnect S1 F1\n" + line + "\nCircle Last 10 10\n";
        BoardFileException refused = catchThrowableOfType(() -> BoardFiles.load("f.txt", text), BoardFileException.class);

        assertThat(refused).as(why).isNotNull();
        assertThat(refused.errors()).as(why).singleElement().satisfies(error -> {
            assertThat(error.source()).isEqualTo("f.txt");
            assertThat(error.line()).isEqualTo(4);
            assertThat(error.text()).isEqualTo(line);
            assertThat(error.reason()).contains(reasonSays);
        });
        LoadResult skipping = BoardFiles.loadSkippingBadLines("f.txt", text);
        assertThat(skipping.skippedLines()).isEqualTo(refused.errors());
        assertThat(skipping.board().gizmo("Last")).as("lines after the bad one still load").isPresent();
    }

    @Test
    void reportsSyntaxAndBoardErrorsTogetherInLineOrder() {
        String text = String.join("\n", "Square S 1 1", "Square T 1 1", "Rhombus X 3 3", "Connect S Ghost",
                "Circle C 4.5 4", "Circle C 4 4");
        BoardFileException refused = catchThrowableOfType(() -> BoardFiles.load("f", text), BoardFileException.class);
        assertThat(refused.errors()).extracting(BoardFileError::line).containsExactly(2, 3, 4, 5);
        assertThat(refused.errors().get(1).reason())
                .isEqualTo("Rhombus X: an extension of another implementation, not part of the format");
    }

    @Test
    void skippingBadLinesLoadsTheRestAndSaysExactlyWhichLinesWereLeftOut() throws BoardFileException {
        String text = String.join("\n", "Square S 1 1", "Rhombus K 3 3", "Circle C 1 1", "Ball B 5.5 5.5 0 0",
                "Connect S C", "KeyConnect key 32 down S");
        LoadResult result = BoardFiles.loadSkippingBadLines("f", text);

        assertThat(result.skippedLines()).extracting(BoardFileError::line, BoardFileError::text).containsExactly(
                tuple(2, "Rhombus K 3 3"),
                tuple(3, "Circle C 1 1"),
                tuple(5, "Connect S C"));
        String withoutSkipped = String.join("\n", "Square S 1 1", "Ball B 5.5 5.5 0 0", "KeyConnect key 32 down S");
        assertThat(BoardContents.of(result.board()))
                .isEqualTo(BoardContents.of(BoardFiles.load("f", withoutSkipped)));
    }

    @Test
    void aCleanFileSkipsNothing() {
        LoadResult result = BoardFiles.loadSkippingBadLines("f", "Square S 1 1\n");
        assertThat(result.skippedLines()).isEmpty();
        assertThat(result.board().gizmos()).extracting(g -> g.kind()).containsExactly(GizmoKind.SQUARE);
    }

    @Test
    void anEmptyFileIsAnEmptyBoard() throws BoardFileException {
        Board board = BoardFiles.load("empty", "");
        assertThat(BoardContents.of(board)).isEqualTo(BoardContents.of(new Board()));
    }
}
