package gizmoball.view;

import static gizmoball.view.Gui.await;

import gizmoball.app.Gizmoball;
import gizmoball.controller.Settings;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.UUID;
import java.util.prefs.Preferences;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;

/**
 * What the GUI tests that play in the game's window share: the player's settings in a preferences node of the test's
 * own, removed after it, and the game launched on a board. They skip without a display, and every window is closed
 * (and its closing, which writes to the node, waited for) after each test.
 */
public abstract class GameWindowFixture {
    protected final Preferences node = Preferences.userRoot().node("/gizmoball-test/" + UUID.randomUUID());
    protected final Settings settings = new Settings(node);
    protected Gizmoball app;

    @BeforeEach
    protected void display() {
        Gui.assumeDisplay();
    }

    @AfterEach
    protected void close() throws Exception {
        Gui.closeAllWindows();
        node.removeNode();
    }

    /** Launches the game on the board file with this test's settings, and waits for its window. */
    protected Gizmoball launch(Path board) {
        app = Gizmoball.launch(board, settings);
        await("the window", () -> app.window().isShowing());
        return app;
    }

    /** Writes {@code text} to {@code file} and launches the game on it, as {@link #launch(Path)}. */
    protected Gizmoball launch(Path file, String text) throws IOException {
        return launch(Files.writeString(file, text));
    }
}
