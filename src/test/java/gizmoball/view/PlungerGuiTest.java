package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.game.KeyPress;
import gizmoball.model.gizmo.AbsorberView;
import java.awt.Component;
import java.awt.KeyboardFocusManager;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Toolkit;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import physics.Vect;

/**
 * A plunger in the window: the hint says to hold and release, the pull is drawn while the key is held (a screenshot
 * in build/screenshots to look at), and the release launches at the pull's speed, also when the real keyboard holds
 * the key through X11's auto-repeat.
 */
class PlungerGuiTest extends GameWindowFixture {
    private static final String LANE = """
            Square S 18 2
            Absorber P 19 19 20 20
            Absorber D 0 19 18 20
            Ball B 19.75 19.75 0.0 0.0
            KeyConnect key 32 down P
            Gravity 25.0
            Friction 0.025 0.025
            #@Plunger P 60.0 1.0
            #@Balls 1
            #@Drain D
            """;
    private static final Path SHOTS = Path.of("build", "screenshots");


    /** Holding the real key through the window (X11's auto-repeat pairs and all) pulls for exactly the ticks held. */
    @Test
    void theKeyboardsHoldIsOnePullOfTheTicksItLasted(@TempDir Path dir) throws Exception {
        launch(dir.resolve("lane.txt"), LANE);
        Robot robot = new Robot();
        Point centre = onEdt(() -> {
            Point p = app.window().boardPanel().getLocationOnScreen();
            return new Point(p.x + app.window().boardPanel().getWidth() / 2,
                    p.y + app.window().boardPanel().getHeight() / 2);
        });
        robot.mouseMove(centre.x, centre.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        await("the board to have the keyboard focus", () -> app.window().boardPanel().isFocusOwner());

        robot.keyPress(KeyEvent.VK_SPACE);
        await("the pull to start", () -> onEdt(() -> !app.session().board().game().keys().isEmpty()));
        for (int i = 0; i < 30; i++) {
            onEdt(() -> {
                app.loop().step();
                // What X11 sends while a key is held: a release and a press together.
                Component focused = KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner();
                long when = System.currentTimeMillis();
                focused.dispatchEvent(new KeyEvent(focused, KeyEvent.KEY_RELEASED, when, 0, KeyEvent.VK_SPACE,
                        KeyEvent.CHAR_UNDEFINED));
                focused.dispatchEvent(new KeyEvent(focused, KeyEvent.KEY_PRESSED, when, 0, KeyEvent.VK_SPACE,
                        KeyEvent.CHAR_UNDEFINED));
            });
        }
        assertThat(pull()).isGreaterThan(0);
        robot.keyRelease(KeyEvent.VK_SPACE);
        await("the launch", () -> onEdt(() -> !app.session().board().ball("B").orElseThrow().isCaptured()));

        List<KeyPress> keys = onEdt(() -> app.session().board().game().keys());
        assertThat(keys).extracting(KeyPress::motion).containsExactly(KeyPress.Motion.DOWN, KeyPress.Motion.UP);
        double held = 0;
        for (long t = keys.get(0).tick(); t < keys.get(1).tick(); t++) {
            held += 1.0 / 60;
        }
        double expected = 10 + 50 * Math.min(held, 1.0);
        assertThat(onEdt(() -> app.session().board().ball("B").orElseThrow().velocity()))
                .isEqualTo(new Vect(0, -expected));
    }

    private double pull() {
        return onEdt(() -> ((AbsorberView) app.session().board().gizmo("P").orElseThrow()).pull());
    }

    @Test
    void holdingTheKeyPullsThePlungerOnScreenAndTheReleaseLaunches(@TempDir Path dir) throws Exception {
        launch(dir.resolve("lane.txt"), LANE);
        assertThat(onEdt(() -> app.gameFeatures().launchHint().current().map(LaunchHint.Hint::text)))
                .hasValue("Hold Space to pull, release to launch");

        onEdt(() -> {
            app.session().board().keyDown(KeyEvent.VK_SPACE);
            for (int i = 0; i < 45; i++) {
                app.loop().step();
            }
        });
        double held = 0;
        for (int i = 0; i < 45; i++) {
            held += 1.0 / 60;   // the board's clock: a sum of its ticks
        }
        assertThat(pull()).isEqualTo(held);
        Gui.sleep(300);
        Files.createDirectories(SHOTS);
        Rectangle screen = new Rectangle(Toolkit.getDefaultToolkit().getScreenSize());
        ImageIO.write(new Robot().createScreenCapture(screen), "png", SHOTS.resolve("plunger-pulled.png").toFile());

        double speed = onEdt(() -> 10 + 50 * pull());
        onEdt(() -> app.session().board().keyUp(KeyEvent.VK_SPACE));
        assertThat(pull()).isZero();
        assertThat(onEdt(() -> app.session().board().ball("B").orElseThrow().velocity()))
                .isEqualTo(new Vect(0, -speed));
    }
}
