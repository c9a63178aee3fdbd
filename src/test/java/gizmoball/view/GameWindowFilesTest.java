package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.app.Gizmoball;
import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import java.awt.Window;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/** Opening, reloading and saving board files through the window (needs a display). */
class GameWindowFilesTest extends WindowOnFiles {
    private static final String BAD = "Square S1 2 2\nSquare S2 x 3\nCircle C1 5 5\nBogus 1 2\n";

    @Test
    void launchOpensTheWindowOnTheBoardFile() throws Exception {
        launch(write("good.txt", GOOD));

        assertThat(gizmoNames()).containsExactly("S1", "C1");
        assertThat(onEdt(window::getTitle)).isEqualTo("Gizmoball - good.txt");
        assertThat(onEdt(() -> window.session().file())).contains(dir.resolve("good.txt"));
    }

    @Test
    void aBadFileShowsItsLineNumberedProblemsAndCanBeKeptOut() throws Exception {
        launch(write("good.txt", GOOD));
        Path bad = write("bad.txt", BAD);

        SwingUtilities.invokeLater(() -> app.files().open(bad));
        JDialog dialog = awaitProblemsDialog();
        List<String> problems = listed(dialog, "loadProblems.list");
        assertThat(problems).hasSize(2);
        assertThat(problems.get(0)).startsWith("line 2: ").contains("Square S2 x 3");
        assertThat(problems.get(1)).startsWith("line 4: ").contains("Bogus 1 2");

        click(dialog, LoadProblemsDialog.KEEP);

        await("the dialog to close", () -> !dialog.isShowing());
        assertThat(gizmoNames()).containsExactly("S1", "C1");
        assertThat(onEdt(() -> window.session().file())).contains(dir.resolve("good.txt"));
        assertThat(onEdt(() -> window.session().board().balls())).hasSize(1);
    }

    @Test
    void aBadFileCanBeLoadedWithoutItsBadLines() throws Exception {
        launch(null);
        Path bad = write("bad.txt", BAD);

        SwingUtilities.invokeLater(() -> app.files().open(bad));
        click(awaitProblemsDialog(), LoadProblemsDialog.SKIP);

        await("the good lines to load", () -> window.session().board().gizmos().size() == 2);
        assertThat(gizmoNames()).containsExactly("S1", "C1");
        assertThat(onEdt(() -> window.statusLine().message())).contains("bad.txt", "2 bad lines");
    }

    @Test
    void launchOnABadFileShowsTheProblemsOnceTheWindowIsUp() throws Exception {
        launch(write("bad.txt", BAD));

        click(awaitProblemsDialog(), LoadProblemsDialog.KEEP);

        assertThat(gizmoNames()).isEmpty();
        assertThat(onEdt(() -> window.isShowing())).isTrue();
    }

    @Test
    void saveWritesTheDesignThatLoadsBackTheSame() throws Exception {
        Path file = write("good.txt", GOOD);
        launch(file);
        for (int i = 0; i < 30; i++) {
            Gui.clickMenu(window.menus(), "Tick");
        }
        onEdt(() -> window.session().markModified());

        Gui.clickMenu(window.menus(), "Save");

        assertThat(onEdt(() -> window.session().isModified())).isFalse();
        Board saved = BoardFiles.load(file);
        assertThat(saved.gizmos()).extracting(Gizmo::name).containsExactly("S1", "C1");
        assertThat(saved.balls()).singleElement()
                .satisfies(b -> assertThat(b.position().y()).as("the design, not the ball in flight").isEqualTo(5));
    }

    @Test
    void reloadReadsTheFileAgain() throws Exception {
        Path file = write("good.txt", GOOD);
        launch(file);
        Files.writeString(file, "Square S9 9 9\n");

        Gui.clickMenu(window.menus(), "Reload");

        assertThat(gizmoNames()).containsExactly("S9");
    }

    @Test
    void aMissingFileIsReportedAndTheBoardKept() throws Exception {
        launch(write("good.txt", GOOD));

        SwingUtilities.invokeLater(() -> app.files().open(dir.resolve("missing.txt")));
        await("an error message", () -> window.statusLine().message().contains("missing.txt"));
        assertThat(onEdt(() -> window.statusLine().message())).contains("no such file");
        for (Window w : Window.getWindows()) {
            if (w instanceof JDialog d && d.isShowing()) {
                onEdt(d::dispose);
            }
        }
        assertThat(gizmoNames()).containsExactly("S1", "C1");
    }

    @Test
    void newAsksBeforeDiscardingUnsavedChanges() throws Exception {
        launch(write("good.txt", GOOD));
        onEdt(() -> window.session().markModified());

        SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), "New").doClick(0));
        await("the unsaved-changes question", () -> unsavedChangesDialog().isPresent());
        onEdt(() -> Gui.find(unsavedChangesDialog().orElseThrow(), JButton.class, b -> "Discard".equals(b.getText()))
                .orElseThrow().doClick(0));

        await("the new board", () -> window.session().board().gizmos().isEmpty());
        assertThat(onEdt(() -> window.session().isModified())).isFalse();
    }

    private static Optional<JDialog> unsavedChangesDialog() {
        return showingDialog(d -> "Unsaved changes".equals(d.getTitle()));
    }
}
