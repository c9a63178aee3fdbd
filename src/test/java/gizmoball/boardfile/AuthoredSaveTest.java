package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.TriggerSource;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Issue 23, item 1: a save keeps what the author wrote and changes only the lines of what was edited. */
class AuthoredSaveTest {
    private static final String COMMENTED = """
            # My board.

            Square S1 2 2
            Circle   C1 5 5
            # the lane
            Absorber A 0 19 20 20

            Ball B 10.5 5 0 0

            Connect S1 C1
            KeyConnect key 32 down A
            Gravity 25
            Friction 0.025 0.025
            """;

    private static LoadResult load(String text) {
        return BoardFiles.loadSkippingBadLines("board.txt", text);
    }

    @Test
    void theDefaultBoardSavedUnchangedIsWrittenAsItWasAndNotAtAll(@TempDir Path dir) throws Exception {
        Path file = Files.copy(Path.of("boards", "default.txt"), dir.resolve("default.txt"));
        FileTime before = FileTime.fromMillis(0);
        Files.setLastModifiedTime(file, before);
        LoadResult loaded = BoardFiles.loadSkippingBadLines(file);

        SavePlan plan = loaded.authored().saving(loaded.board());

        assertThat(plan.text()).isEqualTo(Files.readString(file));
        assertThat(plan.lost().total()).isZero();
        assertThat(BoardFiles.save(plan, file)).as("written").isFalse();
        assertThat(Files.getLastModifiedTime(file)).isEqualTo(before);
    }

    @Test
    void aMovedGizmoChangesOnlyItsOwnLine() {
        LoadResult loaded = load(COMMENTED);
        loaded.board().moveGizmo("C1", 7, 7);

        assertThat(loaded.authored().saving(loaded.board()).text())
                .isEqualTo(COMMENTED.replace("Circle   C1 5 5", "Circle C1 7 7"));
    }

    @Test
    void aDeletedGizmoTakesItsLinesAndTheLinesNamingItWithIt() {
        LoadResult loaded = load(COMMENTED);
        loaded.board().delete("S1");

        assertThat(loaded.authored().saving(loaded.board()).text())
                .isEqualTo(COMMENTED.replace("Square S1 2 2\n", "").replace("Connect S1 C1\n", ""));
    }

    @Test
    void newThingsGoAfterTheLastLineOfTheirSort() {
        LoadResult loaded = load(COMMENTED);
        Board board = loaded.board();
        board.addGizmo(GizmoKind.TRIANGLE, "T1", 9, 9);
        board.rotate("T1");
        board.addBall("B2", 3.5, 3.5, 1, 0);
        board.connect(TriggerSource.OUTER_WALLS, "C1");
        board.bindKey(90, KeyEdge.UP, "A");

        assertThat(loaded.authored().saving(board).text()).isEqualTo("""
                # My board.

                Square S1 2 2
                Circle   C1 5 5
                # the lane
                Absorber A 0 19 20 20
                Triangle T1 9 9
                Rotate T1

                Ball B 10.5 5 0 0
                Ball B2 3.5 3.5 1.0 0.0

                Connect S1 C1
                Connect OuterWalls C1
                KeyConnect key 32 down A
                KeyConnect key 90 up A
                Gravity 25
                Friction 0.025 0.025
                """);
    }

    /**
     * Issue 40 item 7: a key binding written with {@code #@} (it says what the gizmo does) is a key binding: it goes
     * after the last {@code KeyConnect} line, not after the last {@code #@} line of any sort; and never before the
     * line that defines the gizmo it names.
     */
    @Test
    void aMarkedKeyBindingGoesAfterTheLastKeyBindingAndAfterItsGizmo() {
        String text = """
                Square S1 2 2
                Absorber A 0 19 20 20
                KeyConnect key 32 down A
                #@Portal P1 5 5
                #@Rotate P1
                Gravity 25
                """;
        LoadResult loaded = load(text);
        Board board = loaded.board();
        board.bindKey(70, KeyEdge.DOWN, "S1", new gizmoball.model.gizmo.Order(java.util.Optional.empty(), 0.5));
        board.bindKey(71, KeyEdge.DOWN, "P1", new gizmoball.model.gizmo.Order(java.util.Optional.empty(), 0.5));
        board.addGizmo(GizmoKind.PORTAL, "P2", 8, 8);
        board.rotate("P2");
        board.bindKey(72, KeyEdge.DOWN, "P2", new gizmoball.model.gizmo.Order(java.util.Optional.empty(), 0.5));

        assertThat(loaded.authored().saving(board).text()).isEqualTo("""
                Square S1 2 2
                Absorber A 0 19 20 20
                KeyConnect key 32 down A
                #@KeyConnect key 70 down S1 after 0.5
                #@Portal P1 5 5
                #@KeyConnect key 71 down P1 after 0.5
                #@Portal P2 8 8
                #@KeyConnect key 72 down P2 after 0.5
                #@Rotate P1
                #@Rotate P2
                Gravity 25
                """);
    }

    @Test
    void aChangedRotationReplacesAllTheRotateLinesOfItsGizmo() {
        String text = "Triangle T 1 1\nRotate T\n# two more\nRotate T\nRotate T\nGravity 25.0\n";
        LoadResult loaded = load(text);
        loaded.board().rotate("T");

        assertThat(loaded.authored().saving(loaded.board()).text()).isEqualTo("Triangle T 1 1\n# two more\nGravity 25.0\n");
    }

    @Test
    void aChangedConstantIsRewrittenInItsPlaceAndAMissingOneIsAddedAfterItsNeighbours() {
        LoadResult loaded = load("# constants first\nGravity 10\nSquare S 1 1\n");
        loaded.board().setGravity(30);

        assertThat(loaded.authored().saving(loaded.board()).text())
                .isEqualTo("# constants first\nGravity 30.0\nSquare S 1 1\n");
    }

    @Test
    void theHistoryOfAThingThatMovedGoesWithItsOldPlace() {
        LoadResult loaded = load("Square S 1 1\nCircle C 3 3\nMove S 5 5\nMove C 8 8\n");
        loaded.board().moveGizmo("S", 7, 7);

        assertThat(loaded.authored().saving(loaded.board()).text()).isEqualTo("Square S 7 7\nCircle C 3 3\nMove C 8 8\n");
    }

    @Test
    void windowsLineEndsAndAMissingFinalLineBreakAreKept() {
        LoadResult loaded = load("\uFEFF# crlf\r\nSquare S 1 1\r\nCircle C 3 3");
        loaded.board().moveGizmo("S", 2, 2);
        loaded.board().addGizmo(GizmoKind.CIRCLE, "D", 9, 9);

        assertThat(loaded.authored().saving(loaded.board()).text())
                .isEqualTo("\uFEFF# crlf\r\nSquare S 2 2\r\nCircle C 3 3\nCircle D 9 9");
    }

    @Test
    void theLinesTheLoadLeftOutGoAndAreCountedTheCommentsStay() {
        LoadResult loaded = load("# peer file\nSquare S 1 1\nBogus 1 2\n\nSquare T x 3\n");

        SavePlan plan = loaded.authored().saving(loaded.board());

        assertThat(plan.text()).isEqualTo("# peer file\nSquare S 1 1\n\n");
        assertThat(plan.lost()).isEqualTo(new SavePlan.LostLines(2, 0, 0));
        assertThat(plan.lost().describe()).isEqualTo("2 bad lines");
    }

    @Test
    void aTextTheEditedBoardCannotBeWrittenAroundIsWrittenCanonicallyCountingEveryLineThatGoes() {
        // Two balls named B: the second loads as B_2. Moving B_2 adds a line of that name, which would make the
        // second "Ball B" line load under another name: the merge does not load to the edited board.
        LoadResult loaded = load("# two of a name\nBall B 1.5 1.5 0 0\n\nBall B 5.5 5.5 0 0\n");
        loaded.board().moveBall("B_2", 8.5, 8.5);

        SavePlan plan = loaded.authored().saving(loaded.board());

        assertThat(plan.text()).isEqualTo(BoardFiles.toText(loaded.board()));
        assertThat(plan.lost()).isEqualTo(new SavePlan.LostLines(0, 1, 1));
        assertThat(plan.lost().describe()).isEqualTo("1 comment and 1 blank line");
    }

    @Test
    void aNewBoardIsWrittenInTheCanonicalForm() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SQUARE, "S", 1, 1);

        assertThat(SavePlan.canonical(board).text()).isEqualTo(BoardFiles.toText(board));
    }

    @Test
    void theNextSaveStartsFromWhatTheLastOneWrote() {
        LoadResult loaded = load(COMMENTED);
        loaded.board().moveGizmo("C1", 7, 7);
        SavePlan first = loaded.authored().saving(loaded.board());
        loaded.board().moveGizmo("S1", 3, 3);

        assertThat(first.saved().saving(loaded.board()).text())
                .isEqualTo(first.text().replace("Square S1 2 2", "Square S1 3 3"));
    }
}
