package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.controller.Settings;
import gizmoball.session.Mode;
import java.awt.Rectangle;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.UUID;
import java.util.prefs.Preferences;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Issue 23, items 1-7, through the window: files keep what the author wrote, and the File menu's rough edges. */
class AuthorFilesGuiTest extends WindowOnFiles {
    private final Preferences node = Preferences.userRoot().node("/gizmoball-test/" + UUID.randomUUID());
    private final Settings settings = new Settings(node);

    @AfterEach
    void forget() throws Exception {
        Gui.closeAllWindows();   // before the settings go: a closing window writes its place there
        node.removeNode();
    }

    private Path defaultBoardCopy() throws Exception {
        return Files.copy(Path.of("boards", "default.txt"), dir.resolve("default.txt"));
    }

    @Test
    void savingTheDefaultBoardUnchangedWritesNothingAndAnEditChangesOnlyItsLines() throws Exception {
        Path file = defaultBoardCopy();
        String original = Files.readString(file);
        FileTime before = FileTime.fromMillis(0);
        Files.setLastModifiedTime(file, before);
        launch(file, settings);

        Gui.clickMenu(window.menus(), "Save");
        assertThat(Files.getLastModifiedTime(file)).as("not written").isEqualTo(before);
        assertThat(onEdt(() -> window.statusLine().message())).contains("nothing to write");

        onEdt(() -> window.session().setMode(Mode.BUILD));
        onEdt(() -> app.build().controller().select("Skill"));
        Gui.clickMenu(window.menus(), "Delete selection");
        Gui.clickMenu(window.menus(), "Save");

        assertThat(Files.readString(file)).isEqualTo(original.replace("Circle Skill 12 3\n", "")
                .replace("Colour Skill 255 215 0\n", "").replace("#@Points Skill 500\n", ""));
        assertThat(onEdt(window::getTitle)).isEqualTo("Gizmoball - default.txt");
    }

    @Test
    void fileQuitKeepsTheWindowsPlaceAndSize() {
        launch(null, settings);
        Rectangle asked = new Rectangle(30, 50, 900, 760);
        onEdt(() -> window.setBounds(asked));
        await("the window to take its new size", () -> window.getWidth() == asked.width);
        Rectangle placed = onEdt(() -> window.getBounds());

        Gui.clickMenu(window.menus(), "Quit");

        await("the window to close", () -> !window.isDisplayable());
        assertThat(settings.windowBounds()).as("where it was, as a window manager placed it").contains(placed);
    }

    @Test
    void theBoardOpenedAtLaunchIsNoChoiceOfFolderOnlyTheChoosersAre() throws Exception {
        Path chosenBefore = Files.createDirectory(dir.resolve("mine"));
        settings.setLastFolder(chosenBefore);
        launch(write("launched.txt", GOOD), settings);
        assertThat(settings.lastFolder()).contains(chosenBefore);

        Path other = Files.createDirectory(dir.resolve("other"));
        Files.writeString(other.resolve("b.txt"), GOOD);
        SwingUtilities.invokeLater(() -> app.files().open());
        approve(awaitChooser(), other.resolve("b.txt").toFile());

        await("the board to open", () -> window.session().file().isPresent()
                && window.session().file().get().equals(other.resolve("b.txt")));
        assertThat(settings.lastFolder()).contains(other);
    }

    @Test
    void openAcceptsTheNameItSuggestsAfterSaveAsAddedTheExtension() throws Exception {
        launch(null, settings);
        SwingUtilities.invokeLater(() -> app.files().saveAs());
        approve(awaitChooser(), dir.resolve("xyz").toFile());
        await("the save", () -> Files.exists(dir.resolve("xyz.txt")));

        SwingUtilities.invokeLater(() -> app.files().open());
        JFileChooser chooser = awaitChooser();
        onEdt(chooser::approveSelection);

        await("the board to open", () -> window.statusLine().message().equals("Loaded xyz.txt"));
        assertThat(onEdt(() -> window.session().file())).contains(dir.resolve("xyz.txt"));
    }

    @Test
    void cancelOnReplaceReturnsToTheChooser() throws Exception {
        launch(write("good.txt", GOOD), settings);
        Path existing = write("other.txt", "Square S9 9 9\n");

        SwingUtilities.invokeLater(() -> app.files().saveAs());
        approve(awaitChooser(), existing.toFile());
        JDialog question = awaitDialog(d -> "Save As".equals(d.getTitle()));
        click(question, "Cancel");
        await("the question to close", () -> !question.isShowing());

        approve(awaitChooser(), dir.resolve("third.txt").toFile());
        await("the save under another name", () -> Files.exists(dir.resolve("third.txt")));
        assertThat(Files.readString(existing)).isEqualTo("Square S9 9 9\n");
        assertThat(onEdt(() -> window.session().file())).contains(dir.resolve("third.txt"));
    }

    @Test
    void aSampleBoardShowsItsNameInTheTitleAndTheStatusLine() {
        launch(null, settings);
        onEdt(() -> app.files().openSample("default.txt"));

        assertThat(onEdt(window::getTitle)).isEqualTo("Gizmoball - default.txt (sample)");
        await("the status line to name it", () -> window.statusLine().text().contains("default.txt (sample)"));
    }

    @Test
    void clearBoardThenUndoIsBackToTheSavedBoard() throws Exception {
        launch(write("good.txt", GOOD), settings);
        onEdt(() -> window.session().setMode(Mode.BUILD));

        SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), "Clear board\u2026").doClick(0));
        click(awaitDialog(d -> "Clear board".equals(d.getTitle())), "OK");
        await("the board to clear", () -> window.session().board().gizmos().isEmpty());
        assertThat(onEdt(window::getTitle)).isEqualTo("Gizmoball - good.txt *");

        onEdt(() -> app.build().controller().undo());
        assertThat(onEdt(window::getTitle)).isEqualTo("Gizmoball - good.txt");
    }

    @Test
    void openRecentListsTheBoardsOpenedAndReopensOne() throws Exception {
        Path first = write("first.txt", GOOD);
        launch(first, settings);
        Path second = write("second.txt", "Square S9 9 9\n");
        onEdt(() -> app.files().open(second));

        javax.swing.JMenu recent = onEdt(() -> {
            javax.swing.JMenu file = window.menus().getMenu(0);
            for (int i = 0; i < file.getItemCount(); i++) {
                if (file.getItem(i) != null && "file.recent".equals(file.getItem(i).getName())) {
                    return (javax.swing.JMenu) file.getItem(i);
                }
            }
            throw new AssertionError("no Open recent in " + file.getText());
        });
        assertThat(onEdt(() -> recent.getItemCount())).isEqualTo(2);
        assertThat(onEdt(() -> recent.getItem(0).getText())).contains("second.txt");
        onEdt(() -> recent.getItem(1).doClick(0));

        assertThat(onEdt(() -> window.session().file())).contains(first);
        assertThat(settings.recentFiles()).containsExactly(first, second);
    }

    @Test
    void theFirstRunSaysHowToStartAndWhichKeysPlayTheBoardOnce() throws Exception {
        launch(defaultBoardCopy(), settings);
        await("the hint", () -> window.statusLine().message().startsWith("Press Start (Ctrl+G) to play"));
        assertThat(onEdt(() -> window.statusLine().message())).contains("Z: left flipper LF (hold)", "Ctrl+K");
        onEdt(window::dispose);

        launch(dir.resolve("default.txt"), settings);
        onEdt(() -> { });
        assertThat(onEdt(() -> window.statusLine().message())).isEqualTo("Loaded default.txt");
    }

    /**
     * Issue 40 item 4: at the window's first size the hint shows whole (keys that do not fit are left to Help, never
     * cut mid-word), and starting the game takes it away.
     */
    @Test
    void theFirstRunHintFitsTheLineWholeAndGoesWhenTheGameStarts() throws Exception {
        launch(defaultBoardCopy(), settings);
        await("the hint", () -> window.statusLine().message().startsWith("Press Start (Ctrl+G) to play"));
        String hint = onEdt(() -> window.statusLine().message());
        javax.swing.JLabel shown = onEdt(() -> Gui.find(window.statusLine(), javax.swing.JLabel.class,
                l -> "status.message".equals(l.getName())).orElseThrow());
        onEdt(() -> window.statusLine().doLayout());
        assertThat(onEdt(shown::getText)).as("the message as the line shows it").isEqualTo(hint);
        assertThat(hint).contains("Z: left flipper LF (hold)", "Ctrl+K");

        Gui.clickMenu(window.menus(), "Start");
        await("the hint gone", () -> !window.statusLine().message().startsWith("Press Start"));
    }
}
