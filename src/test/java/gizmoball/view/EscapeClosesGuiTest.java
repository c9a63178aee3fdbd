package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import java.awt.event.KeyEvent;
import java.nio.file.Path;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/** Issue 40 item 6: Escape closes every dialog the window opens, as the player expects of a dialog. */
class EscapeClosesGuiTest extends WindowOnFiles {
    /** Escape pressed with the focus inside the dialog (wherever it is, the dialog hears it). */
    private static void pressEscape(JDialog dialog) {
        onEdt(() -> {
            JComponent inside = (JComponent) dialog.getContentPane();
            inside.dispatchEvent(new KeyEvent(inside, KeyEvent.KEY_PRESSED, System.currentTimeMillis(), 0,
                    KeyEvent.VK_ESCAPE, KeyEvent.CHAR_UNDEFINED));
        });
    }

    private void escapeCloses(String menuItem, java.util.function.Predicate<JDialog> which) {
        SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), menuItem).doClick(0));
        JDialog dialog = awaitDialog(which);
        pressEscape(dialog);
        await(menuItem + " closed by Escape", () -> !dialog.isShowing());
    }

    @Test
    void escapeClosesTheHighScoresTheHelpAndTheKeys() throws Exception {
        launch(write("board.txt", GOOD));
        await("the window", window::isShowing);
        escapeCloses("High scores...", d -> "highscores.dialog".equals(d.getName()));
        escapeCloses(HelpPages.HOW_TO_PLAY + "...", d -> "help".equals(d.getName()));
        escapeCloses("Keys of this board...", d -> d.getTitle().startsWith("Keys of"));
    }

    @Test
    void escapeClosesTheProblemsOfALoadKeepingTheBoard() throws Exception {
        launch(write("board.txt", GOOD));
        Path bad = write("bad.txt", "Square S 1 1\nRhombus X 5 5\n");
        SwingUtilities.invokeLater(() -> app.files().open(bad));
        JDialog dialog = awaitProblemsDialog();
        pressEscape(dialog);
        await("the problems closed by Escape", () -> !dialog.isShowing());
        assertThat(gizmoNames()).as("the board kept").containsExactly("S1", "C1");
    }
}
