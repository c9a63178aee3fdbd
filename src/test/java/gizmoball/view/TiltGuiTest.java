package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.app.Gizmoball;
import gizmoball.controller.Settings;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Toolkit;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.UUID;
import java.util.prefs.Preferences;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A tilt in the window: the warning, then TILT in the score strip and the status line (a screenshot to look at). */
class TiltGuiTest {
    /** No gravity: the ball flies up and down the right column for a while, free to be nudged. */
    private static final String NUDGEABLE = """
            Absorber A 0 19 20 20
            Ball B 19.75 19.75 0.0 0.0
            KeyConnect key 32 down A
            Gravity 0.0
            Friction 0.0 0.0
            #@Balls 2
            #@Nudge 4.0 37 39 38
            #@Tilt 3 5.0
            #@Drain A
            """;
    private static final Path SHOTS = Path.of("build", "screenshots");

    private final Preferences node = Preferences.userRoot().node("/gizmoball-test/" + UUID.randomUUID());
    private Gizmoball app;

    @BeforeEach
    void display() {
        Gui.assumeDisplay();
    }

    @AfterEach
    void close() throws Exception {
        Gui.closeAllWindows();   // and waits for their closing, which writes to the node
        node.removeNode();
    }

    private void nudgeUp() {
        onEdt(() -> {
            app.session().board().keyDown(KeyEvent.VK_UP);
            app.session().board().keyUp(KeyEvent.VK_UP);
            app.loop().step();
        });
    }

    @Test
    void nudgingTooOftenWarnsThenTilts(@TempDir Path dir) throws Exception {
        app = Gizmoball.launch(Files.writeString(dir.resolve("nudge.txt"), NUDGEABLE), new Settings(node));
        await("the window", () -> app.window().isShowing());
        onEdt(() -> {
            app.session().board().keyDown(KeyEvent.VK_SPACE);
            app.session().board().keyUp(KeyEvent.VK_SPACE);
            app.loop().step();
        });
        nudgeUp();
        nudgeUp();
        assertThat(onEdt(() -> app.window().statusLine().text())).contains("Careful: one more nudge tilts!");
        nudgeUp();
        assertThat(onEdt(() -> app.window().statusLine().text())).contains("TILT");
        assertThat(onEdt(() -> app.gameFeatures().scorePanel().cells().stream().map(ScorePanel.Cell::text).toList()))
                .containsExactly("Score 0", "TILT", "Best -");
        Gui.sleep(300);
        Files.createDirectories(SHOTS);
        Rectangle screen = new Rectangle(Toolkit.getDefaultToolkit().getScreenSize());
        ImageIO.write(new Robot().createScreenCapture(screen), "png", SHOTS.resolve("tilt.png").toFile());
    }
}
