package gizmoball.view;

import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Toolkit;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A tilt in the window: the warning, then TILT in the score strip and the status line (a screenshot to look at). */
class TiltGuiTest extends GameWindowFixture {
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


    private void nudgeUp() {
        onEdt(() -> {
            app.session().board().keyDown(KeyEvent.VK_UP);
            app.session().board().keyUp(KeyEvent.VK_UP);
            app.loop().step();
        });
    }

    @Test
    void nudgingTooOftenWarnsThenTilts(@TempDir Path dir) throws Exception {
        launch(dir.resolve("nudge.txt"), NUDGEABLE);
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
