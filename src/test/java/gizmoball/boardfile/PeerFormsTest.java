package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.groups.Tuple.tuple;

import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;
import java.awt.event.KeyEvent;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import physics.Vect;

/**
 * What boards of other implementations write, one form per test, each on a fixture of src/test/resources/peer-forms:
 * read as meant, with a note on its line where it is not our canonical form; notes never make a load fail.
 */
class PeerFormsTest {

    static String fixture(String name) throws IOException {
        try (InputStream in = PeerFormsTest.class.getResourceAsStream("/peer-forms/" + name)) {
            assertThat(in).as(name + " on the test class path").isNotNull();
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    /** Loads strictly (so any error fails the test) and returns the result with its notes. */
    private static LoadResult strict(String name) throws IOException, BoardFileException {
        String text = fixture(name);
        Board board = BoardFiles.load(name, text);
        LoadResult result = BoardFiles.loadSkippingBadLines(name, text);
        assertThat(result.skippedLines()).isEmpty();
        assertThat(BoardContents.of(result.board())).isEqualTo(BoardContents.of(board));
        return result;
    }

    private static List<String> notesOn(LoadResult result, int line) {
        return result.notes().stream().filter(n -> n.line() == line).map(BoardFileNote::note).toList();
    }

    @Test
    void aReferenceToALaterGizmoIsAppliedRightAfterTheLineThatDefinesIt() throws IOException {
        LoadResult result = BoardFiles.loadSkippingBadLines("f", fixture("forward-references.txt"));
        Board board = result.board();

        assertThat(board.connections()).containsExactly(new Connection(TriggerSource.gizmo("C1"), "LF"));
        assertThat(board.keyBindings()).containsExactly(new KeyBinding(90, KeyEdge.DOWN, "LF"));
        assertThat(board.gizmo("T").orElseThrow().rotation()).isEqualTo(1);
        assertThat(board.ball("B").orElseThrow().position()).as("Move after Move keeps its order")
                .isEqualTo(new Vect(7.5, 6.5));
        assertThat(board.gizmo("S").orElseThrow().x()).as("Delete then a new S: the new one stays").isEqualTo(14);
        assertThat(result.skippedLines()).as("a name never defined is still an error, at the referring line")
                .extracting(BoardFileError::line, BoardFileError::reason)
                .containsExactly(tuple(7, "no gizmo named Nowhere"));
        assertThat(notesOn(result, 2)).containsExactly("applied after line 9, which defines LF");
        assertThat(notesOn(result, 4)).containsExactly("applied after line 10, which defines T");
        assertThat(notesOn(result, 5)).containsExactly("applied after line 11, which defines B");
    }

    @Test
    void aReferenceWaitsOnlyForALaterDefinition() throws BoardFileException {
        Board board = BoardFiles.load("f", String.join("\n", "Square S 1 1", "Rotate S", "Delete S",
                "Square S 2 2"));
        assertThat(board.gizmo("S").orElseThrow().rotation()).as("the new S is not turned").isZero();
        assertThat(board.gizmo("S").orElseThrow().x()).isEqualTo(2);
    }

    @Test
    void coloursInAllFourSpellingsAndAnyCaseBecomeTheGizmosRgb() throws IOException, BoardFileException {
        LoadResult result = strict("colours.txt");
        Board board = result.board();

        assertThat(board.gizmo("RF137").orElseThrow().colour()).contains(new Rgb(255, 255, 0));
        assertThat(board.gizmo("s17").orElseThrow().colour()).as("0xFF0000FF, opaque blue")
                .contains(new Rgb(0, 0, 255));
        assertThat(board.gizmo("S0904").orElseThrow().colour()).contains(new Rgb(0, 255, 0));
        assertThat(board.gizmo("T1").orElseThrow().colour()).contains(new Rgb(0x99, 0xb3, 0xff));
        assertThat(board.gizmo("Plain").orElseThrow().colour()).isEmpty();
        assertThat(notesOn(result, 7)).as("the canonical spelling").isEmpty();
        assertThat(notesOn(result, 8)).containsExactly("read as Colour s17 0 0 255");
        assertThat(notesOn(result, 9)).containsExactly("read as Colour S0904 0 255 0");
        assertThat(notesOn(result, 10)).containsExactly("read as Colour T1 153 179 255");
    }

    @Test
    void saveWritesOneCanonicalColourLinePerColouredGizmoAndReadsItBack() throws IOException, BoardFileException {
        Board board = BoardFiles.load("f", fixture("colours.txt"));
        String saved = BoardFiles.toText(board);

        assertThat(saved.lines().filter(l -> l.startsWith("Colour"))).containsExactly("Colour RF137 255 255 0",
                "Colour s17 0 0 255", "Colour S0904 0 255 0", "Colour T1 153 179 255");
        assertThat(BoardContents.of(BoardFiles.load("saved", saved))).isEqualTo(BoardContents.of(board));
    }

    @Test
    void aBoardWithoutOwnColoursSavesExactlyAsBefore() throws BoardFileException {
        Board board = BoardFiles.load("f", "Square S 1 1\nCircle C 3 3\n");
        board.setColour("S", Optional.of(new Rgb(1, 2, 3)));
        board.setColour("S", Optional.empty());
        assertThat(BoardFiles.toText(board)).isEqualTo("Square S 1 1\nCircle C 3 3\nGravity 25.0\n"
                + "Friction 0.025 0.025\n");
    }

    @Test
    void keySpellingsOfOtherSaversBindWhatTheyMean() throws IOException, BoardFileException {
        LoadResult result = strict("key-spellings.txt");

        assertThat(result.board().keyBindings()).containsExactly(
                new KeyBinding(81, KeyEdge.DOWN, "LF92"),
                new KeyBinding(81, KeyEdge.UP, "LF92"),
                new KeyBinding(87, KeyEdge.CHANGE, "RF112"),
                new KeyBinding(KeyEvent.VK_SPACE, KeyEdge.CHANGE, "A"),
                new KeyBinding(KeyEvent.VK_LEFT, KeyEdge.DOWN, "LF92"),
                new KeyBinding(KeyEvent.VK_Q, KeyEdge.UP, "RF112"),
                new KeyBinding(KeyEvent.VK_Z, KeyEdge.DOWN, "RF112"),
                new KeyBinding(32, KeyEdge.DOWN, "LF92"));
        assertThat(notesOn(result, 4)).containsExactly("'ondown' read as down");
        assertThat(notesOn(result, 5)).containsExactly("'ONUP' read as up");
        assertThat(notesOn(result, 6)).isEmpty();
        assertThat(notesOn(result, 7)).containsExactly("key Space read as key code 32");
        assertThat(notesOn(result, 8)).containsExactly("key \"Left\" read as key code 37");
        assertThat(notesOn(result, 11)).containsExactly("target LF92 written twice: read once");
    }

    @Test
    void aChangeKeyTogglesAFlipperAsAHitDoesAndIsSavedAsChange() throws IOException, BoardFileException {
        Board board = strict("key-spellings.txt").board();
        FlipperView right = (FlipperView) board.gizmo("RF112").orElseThrow();
        board.keyDown(87);
        board.keyUp(87);
        assertThat(right.isActive()).isTrue();
        board.keyDown(87);
        assertThat(right.isActive()).isFalse();
        assertThat(BoardFiles.toText(board)).contains("KeyConnect key 87 change RF112\n");
    }

    @Test
    void leftAndRightFlipperAsTwoWords() throws IOException, BoardFileException {
        LoadResult result = strict("two-word-flippers.txt");
        assertThat(result.board().gizmos()).extracting(Gizmo::name, Gizmo::kind, Gizmo::x, Gizmo::y).containsExactly(
                tuple("LF92", GizmoKind.LEFT_FLIPPER, 9, 2), tuple("RF112", GizmoKind.RIGHT_FLIPPER, 12, 2));
        assertThat(notesOn(result, 1)).containsExactly("'Left Flipper' read as LeftFlipper");
    }

    @Test
    void aGenericFlipperTakesItsSideFromItsName() throws IOException, BoardFileException {
        LoadResult result = strict("generic-flippers.txt");
        assertThat(result.board().gizmos()).extracting(Gizmo::name, Gizmo::kind).containsExactly(
                tuple("LF1", GizmoKind.LEFT_FLIPPER), tuple("rf10", GizmoKind.RIGHT_FLIPPER));
        assertThat(notesOn(result, 2)).containsExactly("Flipper rf10 read as RightFlipper (from its name)");
    }

    @Test
    void leftflipperInOneCaseIsALeftFlipper() throws IOException, BoardFileException {
        LoadResult result = strict("leftflipper-one-case.txt");
        assertThat(result.board().gizmos()).extracting(Gizmo::kind)
                .containsExactly(GizmoKind.LEFT_FLIPPER, GizmoKind.RIGHT_FLIPPER);
        assertThat(result.notes()).as("letter case is tolerated everywhere, silently").isEmpty();
    }

    @Test
    void anAbsorberWithItsCornersInReverseOrderCoversTheSameCells() throws IOException, BoardFileException {
        LoadResult result = strict("absorber-corners-reversed.txt");
        assertThat(result.board().gizmos()).extracting(Gizmo::name, Gizmo::x, Gizmo::y, Gizmo::width, Gizmo::height)
                .containsExactly(tuple("A", 0, 18, 20, 2), tuple("B", 3, 1, 1, 6), tuple("C", 10, 5, 8, 7));
        assertThat(notesOn(result, 2)).containsExactly("corners given in reverse order: read as Absorber B 3 1 4 7");
    }

    @Test
    void aBallWithoutVelocityStartsAtRest() throws IOException, BoardFileException {
        LoadResult result = strict("ball-at-rest.txt");
        BallView ball = result.board().ball("B").orElseThrow();
        assertThat(ball.position()).isEqualTo(new Vect(1, 11));
        assertThat(ball.velocity()).isEqualTo(Vect.ZERO);
        assertThat(notesOn(result, 1)).containsExactly("no velocity given: the ball starts at rest");
    }

    @Test
    void ballsWithOneNameAreRenamedUniquelyButGizmosWithOneNameStayAnError() throws IOException {
        LoadResult result = BoardFiles.loadSkippingBadLines("f", fixture("duplicate-ball-names.txt"));

        assertThat(result.board().balls()).extracting(BallView::name, b -> b.position().x())
                .containsExactly(tuple("B", 2.5), tuple("B_3", 4.5), tuple("B_2", 6.5), tuple("B_4", 8.5));
        assertThat(result.board().ball("B").orElseThrow().position().y()).as("Move B moves the first B").isEqualTo(5.5);
        assertThat(notesOn(result, 2)).containsExactly("ball B renamed B_3: line 1 has a ball of that name");
        assertThat(notesOn(result, 4)).containsExactly("ball B renamed B_4: line 1 has a ball of that name");
        assertThat(result.skippedLines()).extracting(BoardFileError::line, BoardFileError::reason)
                .containsExactly(tuple(7, "name S is already used"));
    }

    @Test
    void overlappingBallsAreLoadedWithANotePerPairAndTheEditorStillRefusesThem() throws IOException,
            BoardFileException {
        LoadResult result = strict("overlapping-balls.txt");

        assertThat(result.board().balls()).extracting(BallView::name).containsExactly("A", "B", "C", "D", "E");
        assertThat(result.notes()).extracting(BoardFileNote::line, BoardFileNote::note).containsExactly(
                tuple(3, "ball B overlaps ball A: loaded; the two pass through each other until they separate"),
                tuple(4, "ball C overlaps ball A: loaded; the two pass through each other until they separate"),
                tuple(4, "ball C overlaps ball B: loaded; the two pass through each other until they separate"));
        assertThatThrownBy(() -> result.board().addBall("F", 15.1, 15, 0, 0)).isInstanceOf(BoardEditException.class)
                .hasMessageContaining("would overlap ball E");
    }

    @Test
    void whatStaysRefusedSaysPreciselyWhy() throws IOException {
        LoadResult result = BoardFiles.loadSkippingBadLines("f", fixture("refused-forms.txt"));

        assertThat(result.skippedLines()).extracting(BoardFileError::line, BoardFileError::reason).containsExactly(
                tuple(1, "Rhombus SP1: an extension of another implementation, not part of the format"),
                tuple(2, "wrong number of arguments: 'Teleporter' of another implementation is read as #@Portal,"
                        + " which takes 3 (#@Portal <name> <x> <y>), found 5: a portal and the cell of its exit on one"
                        + " line, another implementation's form whose exit has no name; this game's portals are two"
                        + " gizmos, each #@Portal <name> <x> <y>, joined by #@Pair"),
                tuple(3, "MouseConnect: an extension of another implementation, not part of the format"),
                tuple(4, "x coordinate 250 is far outside the 20x20 board: pixel coordinates, it seems, but the"
                        + " format counts in L (cells)"),
                tuple(5, "y coordinate 100 is far outside the 20x20 board: pixel coordinates, it seems, but the"
                        + " format counts in L (cells)"),
                tuple(6, "x coordinate 12.25 is not a whole cell: gizmos sit on whole cells, the format has no"
                        + " fractional cells"),
                tuple(7, "an MIT 6.170 3-D form (a gizmo with x y z and a size), not part of the format"),
                tuple(8, "an MIT 6.170 3-D form (a rotation in a plane of axes), not part of the format"),
                tuple(9, "an MIT 6.170 3-D form (an absorber with x y z corners), not part of the format"),
                tuple(10, "an MIT 6.170 3-D form (a ball with x y z and its velocity), not part of the format"),
                tuple(11, "an MIT 6.170 3-D form (a gravity vector), not part of the format"),
                tuple(13, "no gizmo named SP1; line 1, which would define SP1, was refused"));
        assertThat(result.board().gizmos()).extracting(Gizmo::name).containsExactly("Kept");
    }

    @Test
    void notesNeverBlockAStrictLoad() throws IOException, BoardFileException {
        String text = fixture("colours.txt") + fixture("ball-at-rest.txt");
        Board board = BoardFiles.load("f", text);
        assertThat(board.ball("B")).isPresent();
        LoadResult result = BoardFiles.loadSkippingBadLines("f", text);
        assertThat(result.skippedLines()).isEmpty();
        assertThat(result.notes()).extracting(BoardFileNote::line).containsExactly(8, 9, 10, 11);
        assertThat(result.notes().get(0)).hasToString(
                "f:8: read as Colour s17 0 0 255: colour s17 -16776961");
    }
}
