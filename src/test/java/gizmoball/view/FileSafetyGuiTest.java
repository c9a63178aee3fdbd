package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.app.Gizmoball;
import gizmoball.boardfile.BoardFiles;
import gizmoball.model.gizmo.Gizmo;
import java.awt.Component;
import java.awt.Container;
import java.awt.Robot;
import java.awt.event.KeyEvent;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JTextArea;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/** Issue 12, items 1-6: the window never loses a board or a file's lines without asking (needs a display). */
class FileSafetyGuiTest extends WindowOnFiles {
    /** Two of its five lines are bad. */
    private static final String BAD = "Square S1 2 2\nSquare S2 x 3\nCircle C1 5 5\nBogus 1 2\nBall B 10.5 5 0 0\n";

    private void loadSkipping(Path file) {
        SwingUtilities.invokeLater(() -> app.files().open(file));
        click(awaitProblemsDialog(), LoadProblemsDialog.SKIP);
        await("the good lines to load", () -> window.session().file().isPresent()
                && window.session().file().get().equals(file));
    }

    @Test
    void saveAfterLoadingSkippingBadLinesAsksFirstNamingHowManyLinesTheFileWouldLose() throws Exception {
        launch(null);
        Path file = write("peer.txt", BAD);
        loadSkipping(file);
        assertThat(onEdt(window::getTitle)).as("a board without some of its file's lines is unsaved")
                .isEqualTo("Gizmoball - peer.txt *");

        SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), "Save").doClick(0));
        JDialog question = awaitDialog(d -> "Save would lose lines".equals(d.getTitle()));
        assertThat(text(question)).contains("peer.txt", "2 bad lines");
        assertThat(buttons(question)).containsExactly("Save As...", "Save and lose 2 bad lines", "Cancel");
        click(question, "Cancel");

        await("the question to close", () -> !question.isShowing());
        assertThat(Files.readString(file)).as("nothing written").isEqualTo(BAD);
        assertThat(onEdt(() -> window.session().isModified())).isTrue();

        SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), "Save").doClick(0));
        click(awaitDialog(d -> "Save would lose lines".equals(d.getTitle())), "Save and lose 2 bad lines");
        await("the save", () -> !window.session().isModified());
        assertThat(BoardFiles.load(file).gizmos()).extracting(Gizmo::name).containsExactly("S1", "C1");
        assertThat(Files.readString(file)).doesNotContain("S2", "Bogus");
        assertThat(onEdt(window::getTitle)).isEqualTo("Gizmoball - peer.txt");
    }

    @Test
    void theLossQuestionOffersSaveAsWhichLeavesTheFileWhole() throws Exception {
        launch(null);
        Path file = write("peer.txt", BAD);
        loadSkipping(file);

        SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), "Save").doClick(0));
        click(awaitDialog(d -> "Save would lose lines".equals(d.getTitle())), "Save As...");
        approve(awaitChooser(), dir.resolve("copy.txt").toFile());

        await("the save as", () -> Files.exists(dir.resolve("copy.txt")));
        assertThat(Files.readString(file)).isEqualTo(BAD);
        assertThat(onEdt(() -> window.session().file())).contains(dir.resolve("copy.txt"));
        assertThat(onEdt(() -> window.session().linesLostBySaving())).isZero();
    }

    @Test
    void aFileWhoseEveryLineIsBadIsNotOfferedForLoadingSkippingThem() throws Exception {
        launch(write("good.txt", GOOD));
        Path bad = write("all-bad.txt", "Bogus 1 2\nSquare S x 1\n");

        SwingUtilities.invokeLater(() -> app.files().open(bad));
        JDialog dialog = awaitDialog(d -> "loadProblems".equals(d.getName()));
        assertThat(buttons(dialog)).containsExactly(LoadProblemsDialog.KEEP);
        assertThat(text(dialog)).contains("Nothing in all-bad.txt can be loaded");
        click(dialog, LoadProblemsDialog.KEEP);

        await("the dialog to close", () -> !dialog.isShowing());
        assertThat(gizmoNames()).containsExactly("S1", "C1");
        assertThat(onEdt(() -> window.session().file())).contains(dir.resolve("good.txt"));
    }

    @Test
    void saveKeepsTheFilesPermissionBits() throws Exception {
        Path file = write("good.txt", GOOD);
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-r--r--"));
        launch(file);
        onEdt(() -> window.session().markModified());

        Gui.clickMenu(window.menus(), "Save");

        assertThat(onEdt(() -> window.session().isModified())).isFalse();
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(file))).isEqualTo("rw-r--r--");
    }

    @Test
    void saveIntoAMissingFolderSaysSo() throws Exception {
        launch(write("good.txt", GOOD));
        Path missing = dir.resolve("no-such-dir");

        SwingUtilities.invokeLater(() -> app.files().saveAs());
        approve(awaitChooser(), missing.resolve("b.txt").toFile());

        await("the error", () -> window.statusLine().message().startsWith("Cannot save"));
        assertThat(onEdt(() -> window.statusLine().message()))
                .isEqualTo("Cannot save " + missing.resolve("b.txt") + ": the folder " + missing + " does not exist");
        assertThat(text(awaitDialog(d -> "Gizmoball".equals(d.getTitle()))))
                .contains("the folder " + missing + " does not exist");
    }

    @Test
    void saveAsAddsTxtToANameWithoutExtension() throws Exception {
        launch(write("good.txt", GOOD));

        SwingUtilities.invokeLater(() -> app.files().saveAs());
        approve(awaitChooser(), dir.resolve("my board").toFile());

        await("the save", () -> Files.exists(dir.resolve("my board.txt")));
        assertThat(dir.resolve("my board")).doesNotExist();
        assertThat(onEdt(() -> window.session().file())).contains(dir.resolve("my board.txt"));
    }

    @Test
    void saveAsAsksBeforeReplacingTheFileTheAddedExtensionNames() throws Exception {
        launch(write("good.txt", GOOD));
        Path existing = write("other.txt", "Square S9 9 9\n");

        SwingUtilities.invokeLater(() -> app.files().saveAs());
        approve(awaitChooser(), dir.resolve("other").toFile());
        JDialog question = awaitDialog(d -> "Save As".equals(d.getTitle()));
        assertThat(text(question)).contains("other.txt already exists");
        click(question, "Cancel");

        await("the question to close", () -> !question.isShowing());
        assertThat(Files.readString(existing)).isEqualTo("Square S9 9 9\n");
    }

    @Test
    void reloadAsksToDiscardTheChangesAndEnterCancels() throws Exception {
        Path file = write("good.txt", GOOD);
        launch(file);
        onEdt(() -> window.session().board().delete("S1"));
        onEdt(() -> window.session().markModified());

        SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), "Reload").doClick(0));
        JDialog question = awaitDialog(d -> "Reload".equals(d.getTitle()));
        assertThat(text(question)).contains("Discard your changes to good.txt and reload it from disk?");
        assertThat(buttons(question)).containsExactly("Reload", "Cancel");
        await("the question to have the focus", () -> question.isFocused());
        Robot robot = new Robot();
        robot.keyPress(KeyEvent.VK_ENTER);
        robot.keyRelease(KeyEvent.VK_ENTER);

        await("the question to close", () -> !question.isShowing());
        assertThat(gizmoNames()).as("nothing reverted").containsExactly("C1");
        assertThat(onEdt(() -> window.session().isModified())).isTrue();
        assertThat(Files.readString(file)).as("nothing saved").isEqualTo(GOOD);

        SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), "Reload").doClick(0));
        click(awaitDialog(d -> "Reload".equals(d.getTitle())), "Reload");
        await("the reload", () -> window.session().board().gizmos().size() == 2);
        assertThat(onEdt(() -> window.session().isModified())).isFalse();
    }
}
