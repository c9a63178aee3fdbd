package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.clickMenu;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.app.Gizmoball;
import gizmoball.controller.Settings;
import gizmoball.editor.Tool;
import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import java.awt.Component;
import java.awt.Container;
import java.awt.GraphicsEnvironment;
import java.awt.Rectangle;
import java.awt.Window;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Optional;
import java.util.UUID;
import java.util.prefs.Preferences;
import javax.swing.JDialog;
import javax.swing.JEditorPane;
import javax.swing.JLabel;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Issue 12, items 17-20: status line, window placement, modal pause and help (needs a display). */
class PlayWindowGuiTest {
    /** Settings of their own, so that no window place remembered by another test moves the window. */
    private final Preferences node = Preferences.userRoot().node("/gizmoball-test/" + UUID.randomUUID());
    private Gizmoball app;
    private GameWindow window;

    @BeforeEach
    void open() {
        Gui.assumeDisplay();
        app = Gizmoball.launch(null, new Settings(node));
        window = app.window();
        onEdt(() -> {
            Board board = new Board();
            board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 6, 15);
            board.addAbsorber("A", 0, 19, 20, 20);
            board.addBall("B", 10.5, 5, 0, 0);
            board.bindKey(KeyEvent.VK_Z, KeyEdge.DOWN, "LF");
            board.bindKey(KeyEvent.VK_Z, KeyEdge.UP, "LF");
            board.bindKey(KeyEvent.VK_SPACE, KeyEdge.DOWN, "A");
            window.session().load(board, null);
        });
    }

    @AfterEach
    void close() throws Exception {
        Gui.closeAllWindows();
        node.removeNode();
    }

    private String status() {
        return onEdt(() -> window.statusLine().text());
    }

    private double time() {
        return onEdt(() -> window.session().board().time());
    }

    @Test
    void theFrameRateShowsOnlyWhileTheGameRuns() {
        assertThat(status()).doesNotContain("fps");
        clickMenu(window.menus(), "Start");
        await("the frame rate", () -> window.statusLine().text().contains("fps"));
        clickMenu(window.menus(), "Stop");
        onEdt(window::refreshStatus);
        assertThat(status()).doesNotContain("fps");
        clickMenu(window.menus(), "Build");
        onEdt(window::refreshStatus);
        assertThat(status()).doesNotContain("fps");
    }

    @Test
    void resetSaysWhatItDid() {
        clickMenu(window.menus(), "Tick");
        clickMenu(window.menus(), "Reset");
        assertThat(onEdt(() -> window.statusLine().message())).startsWith("Reset");
        assertThat(time()).isZero();
    }

    @Test
    void aNarrowWindowStillShowsTheWholeMessage() {
        String name = "a-board-with-a-really-quite-remarkably-long-name-for-testing.txt";
        onEdt(() -> window.session().saved(Path.of("/tmp", name)));
        onEdt(() -> window.statusLine().showMessage("Loaded " + "without its 3 bad lines"));
        onEdt(() -> {
            window.setSize(400, window.getHeight());
            window.validate();
        });
        JLabel message = onEdt(() -> Gui.find(window.statusLine(), JLabel.class,
                l -> "status.message".equals(l.getName())).orElseThrow());
        assertThat(onEdt(() -> message.getWidth())).isGreaterThanOrEqualTo(onEdt(() -> message.getPreferredSize().width));
        assertThat(onEdt(() -> window.statusLine().getToolTipText())).contains(name, "without its 3 bad lines");
    }

    @Test
    void theWindowOpensCentredOnTheScreen() {
        Rectangle screen = onEdt(() -> GraphicsEnvironment.getLocalGraphicsEnvironment().getDefaultScreenDevice()
                .getDefaultConfiguration().getBounds());
        // The X server confirms the window's place and size asynchronously, and until the last confirmation
        // arrives the window reports an earlier one (the packed size at the new place, say): wait for it.
        await("the window centred on the screen, within a pixel, at " + screen, () -> {
            Rectangle bounds = window.getBounds();
            return Math.abs(bounds.getCenterX() - screen.getCenterX()) <= 1
                    && Math.abs(bounds.getCenterY() - screen.getCenterY()) <= 1;
        });
    }

    @Test
    void theGameIsPausedWhileAModalDialogIsOpenAndResumesAfter() {
        clickMenu(window.menus(), "Start");
        await("the game to run", () -> window.session().board().time() > 0.05);

        SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), "Keys of this board...").doClick(0));
        JDialog keys = awaitDialog();
        await("the game to pause while the dialog is open", () -> !app.loop().isRunning());
        double paused = time();
        assertThat(text(keys)).contains(KeyEvent.getKeyText(KeyEvent.VK_Z) + ": left flipper LF (hold)",
                KeyEvent.getKeyText(KeyEvent.VK_SPACE) + ": absorber A (press)");
        onEdt(keys::dispose);

        await("the game to resume", () -> window.session().board().time() > paused + 0.05);
    }

    @Test
    void aGameStoppedWhileTheDialogIsOpenStaysStopped() {
        clickMenu(window.menus(), "Start");
        SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), "Keys of this board...").doClick(0));
        JDialog keys = awaitDialog();
        onEdt(() -> app.loop().stop());
        boolean[] closed = new boolean[1];
        onEdt(() -> keys.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                closed[0] = true;
            }
        }));
        onEdt(keys::dispose);
        // The game's pause sees a dialog's events before the dialog's own listeners do.
        await("the dialog's close to be handled", () -> closed[0]);
        assertThat(onEdt(() -> app.loop().isRunning())).isFalse();
    }

    @Test
    void helpHasAHowToPlayAndABuildModePage() {
        SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), "How to play...").doClick(0));
        JDialog play = awaitDialog();
        assertThat(onEdt(play::getTitle)).isEqualTo("How to play");
        assertThat(page(play)).contains(KeyEvent.getKeyText(KeyEvent.VK_Z) + ": left flipper LF (hold)",
                "Start (Ctrl+G)", "Reload (Ctrl+R)");
        onEdt(play::dispose);

        SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), "Build mode...").doClick(0));
        JDialog build = awaitDialog();
        assertThat(onEdt(build::getTitle)).isEqualTo("Build mode");
        for (Tool tool : Tool.values()) {
            assertThat(page(build)).contains(tool.labelWithShortcut());
        }
    }

    private static JDialog awaitDialog() {
        await("a dialog", () -> showingDialog().isPresent());
        return showingDialog().orElseThrow();
    }

    private static Optional<JDialog> showingDialog() {
        return Arrays.stream(Window.getWindows()).filter(w -> w instanceof JDialog d && d.isShowing())
                .map(JDialog.class::cast).findFirst();
    }

    private static String page(JDialog dialog) {
        return onEdt(() -> {
            JEditorPane pane = Gui.find(dialog.getContentPane(), JEditorPane.class, p -> true).orElseThrow();
            return pane.getDocument().getText(0, pane.getDocument().getLength());
        });
    }

    private static String text(JDialog dialog) {
        return onEdt(() -> {
            StringBuilder all = new StringBuilder();
            collect(dialog.getContentPane(), all);
            return all.toString();
        });
    }

    private static void collect(Container root, StringBuilder all) {
        for (Component c : root.getComponents()) {
            if (c instanceof JLabel l) {
                all.append(l.getText()).append('\n');
            }
            if (c instanceof Container inner) {
                collect(inner, all);
            }
        }
    }
}
