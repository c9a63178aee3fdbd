package gizmoball.session;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.gizmo.GizmoKind;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import physics.Vect;

class GameSessionTest {
    private static final double DT = Board.DEFAULT_TICK;
    private final GameSession session = new GameSession();

    /** A ball in free fall from rest at (10.5, 5): nothing to hit for many ticks. */
    private static Board fallingBall() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SQUARE, "S", 2, 2);
        board.addBall("B", 10.5, 5, 0, 0);
        return board;
    }

    private Vect ballPosition() {
        return session.board().balls().get(0).position();
    }

    @Test
    void startsInPlayModeOnAnUntitledUnmodifiedEmptyBoard() {
        assertThat(session.mode()).isEqualTo(Mode.PLAY);
        assertThat(session.isModified()).isFalse();
        assertThat(session.file()).isEmpty();
        assertThat(session.boardName()).isEqualTo("untitled");
        assertThat(session.board().gizmos()).isEmpty();
    }

    @Test
    void loadingShowsTheBoardInTheSameBoardObjectAndRemembersTheFile() {
        Board shown = session.board();
        session.markModified();

        session.load(fallingBall(), Path.of("boards", "fall.txt"));

        assertThat(session.board()).isSameAs(shown);
        assertThat(shown.gizmo("S")).isPresent();
        assertThat(session.file()).contains(Path.of("boards", "fall.txt"));
        assertThat(session.boardName()).isEqualTo("fall.txt");
        assertThat(session.isModified()).isFalse();
    }

    @Test
    void resetAndBuildModeBringTheBallsBackToTheDesign() {
        session.load(fallingBall(), null);
        for (int i = 0; i < 30; i++) {
            session.board().tick(DT);
        }
        assertThat(ballPosition().y()).isGreaterThan(5);

        session.reset();
        assertThat(ballPosition().y()).isEqualTo(5);

        session.board().tick(DT);
        session.setMode(Mode.BUILD);
        assertThat(ballPosition().y()).isEqualTo(5);
    }

    @Test
    void playStartsFromWhatWasBuilt() {
        session.setMode(Mode.BUILD);
        session.board().addBall("B2", 4.5, 8, 0, 0);
        session.markModified();
        session.setMode(Mode.PLAY);
        session.board().tick(DT);
        assertThat(ballPosition().y()).isGreaterThan(8);

        assertThat(session.boardToSave().balls()).singleElement()
                .satisfies(b -> assertThat(b.position().y()).isEqualTo(8));
        session.reset();
        assertThat(ballPosition().y()).isEqualTo(8);
        assertThat(session.isModified()).as("switching modes keeps the unsaved edits marked").isTrue();
    }

    @Test
    void inBuildModeTheBoardItselfIsSaved() {
        session.setMode(Mode.BUILD);

        assertThat(session.boardToSave()).isSameAs(session.board());
    }

    @Test
    void listenersHearEachRealModeChangeOnce() {
        List<Mode> heard = new ArrayList<>();
        int[] states = new int[1];
        session.addModeListener(heard::add);
        session.addStateListener(() -> states[0]++);

        session.setMode(Mode.PLAY);
        session.setMode(Mode.BUILD);
        session.setMode(Mode.BUILD);
        session.setMode(Mode.PLAY);

        assertThat(heard).containsExactly(Mode.BUILD, Mode.PLAY);
        assertThat(states[0]).isEqualTo(2);
    }

    @Test
    void savingClearsTheModifiedFlagAndNamesTheBoard() {
        int[] states = new int[1];
        session.addStateListener(() -> states[0]++);
        session.markModified();
        session.markModified();
        assertThat(session.isModified()).isTrue();
        assertThat(states[0]).isEqualTo(1);

        session.saved(Path.of("mine.txt"));

        assertThat(session.isModified()).isFalse();
        assertThat(session.boardName()).isEqualTo("mine.txt");
        assertThat(states[0]).isEqualTo(2);
    }

    @Test
    void newBoardIsEmptyUntitledAndUnmodified() {
        session.load(fallingBall(), Path.of("fall.txt"));
        session.markModified();

        session.newBoard();

        assertThat(session.board().gizmos()).isEmpty();
        assertThat(session.board().balls()).isEmpty();
        assertThat(session.file()).isEmpty();
        assertThat(session.isModified()).isFalse();
    }

    @Test
    void aBoardLoadedWithoutSomeOfItsLinesIsUnsavedAndSavingOverItsFileWouldLoseThem() {
        Path file = Path.of("boards", "peer.txt");
        session.loadWithout(fallingBall(), file, 5);

        assertThat(session.isModified()).as("shown as unsaved (*)").isTrue();
        assertThat(session.file()).contains(file);
        assertThat(session.linesLostBySaving()).isEqualTo(5);
    }

    @Test
    void theLostLinesAreForgottenOnceTheBoardIsSavedOrAnotherIsLoaded() {
        session.loadWithout(fallingBall(), Path.of("peer.txt"), 5);
        session.saved(Path.of("copy.txt"));
        assertThat(session.linesLostBySaving()).isZero();
        assertThat(session.isModified()).isFalse();

        session.loadWithout(fallingBall(), Path.of("peer.txt"), 2);
        session.load(fallingBall(), Path.of("clean.txt"));
        assertThat(session.linesLostBySaving()).isZero();
        assertThat(session.isModified()).isFalse();
    }

    @Test
    void loadingWithoutNoLineIsAnOrdinaryLoad() {
        session.loadWithout(fallingBall(), Path.of("clean.txt"), 0);
        assertThat(session.isModified()).isFalse();
        assertThat(session.linesLostBySaving()).isZero();
    }

    @Test
    void aSampleBoardIsShownUnderItsOwnNameAndOfferedUnderItForSaveAs() {
        session.loadSample(fallingBall(), "default.txt");

        assertThat(session.boardName()).isEqualTo("default.txt (sample)");
        assertThat(session.suggestedFileName()).isEqualTo("default.txt");
        assertThat(session.file()).isEmpty();

        session.saved(Path.of("mine.txt"));
        assertThat(session.boardName()).isEqualTo("mine.txt");
        session.newBoard();
        assertThat(session.boardName()).isEqualTo("untitled");
    }

    /** Issue 23, item 7: an edit that brings the design back as it was loaded (an undo) leaves nothing unsaved. */
    @Test
    void anEditBackToTheLoadedDesignIsNoUnsavedChange() {
        session.load(fallingBall(), Path.of("b.txt"));
        session.setMode(Mode.BUILD);
        session.board().clear();
        session.designEdited(GameSessionTest::sameGizmosAndBalls);
        assertThat(session.isModified()).isTrue();

        session.board().replaceContents(fallingBall());
        session.designEdited(GameSessionTest::sameGizmosAndBalls);
        assertThat(session.isModified()).isFalse();
    }

    @Test
    void aDesignLoadedWithoutSomeOfItsLinesStaysUnsavedWhateverTheEdit() {
        session.loadWithout(fallingBall(), Path.of("b.txt"), 1);
        session.setMode(Mode.BUILD);

        session.designEdited(GameSessionTest::sameGizmosAndBalls);
        assertThat(session.isModified()).isTrue();
    }

    @Test
    void anEditAfterASaveIsComparedWithWhatWasSaved() {
        session.setMode(Mode.BUILD);
        session.board().addGizmo(GizmoKind.CIRCLE, "C", 5, 5);
        session.designEdited(GameSessionTest::sameGizmosAndBalls);
        assertThat(session.isModified()).isTrue();
        session.saved(Path.of("c.txt"));

        session.designEdited(GameSessionTest::sameGizmosAndBalls);
        assertThat(session.isModified()).isFalse();
    }

    /** The session may not use the board file's comparison; names and places are enough here. */
    private static boolean sameGizmosAndBalls(Board a, Board b) {
        return describe(a).equals(describe(b));
    }

    private static List<String> describe(Board board) {
        List<String> parts = new ArrayList<>();
        board.gizmos().forEach(g -> parts.add(g.name() + " " + g.x() + " " + g.y()));
        board.balls().forEach(ball -> parts.add(ball.name() + " " + ball.position()));
        return parts;
    }
}
