package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.clickMenu;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.app.Gizmoball;
import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.geom.Rectangle2D;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;

/** Issue 40 item 3: in a large window the physics overlay's panel goes beside the board, covering none of it. */
class PhysicsOverlayGuiTest extends GameWindowFixture {
    /** At the size the window opens in too; the screenshot is docs/playing.md's picture of the overlay. */
    @Test
    void atTheFirstSizeThePanelIsBesideTheBoard() throws Exception {
        Gizmoball app = Gizmoball.launch(Path.of("boards", "multiball.txt"), settings);
        GameWindow window = app.window();
        await("the window", () -> window.isShowing() && window.boardPanel().getWidth() > 100);
        clickMenu(window.menus(), "Ball trails");
        clickMenu(window.menus(), "Physics overlay");
        for (int i = 0; i < 40; i++) {
            onEdt(() -> app.loop().step());
        }
        assertBesideTheBoard(app, "overlay-first");
    }

    @Test
    void inAWindowAsLargeAsTheScreenThePanelIsBesideTheBoard() throws Exception {
        Gizmoball app = Gizmoball.launch(Path.of("boards", "multiball.txt"), settings);
        GameWindow window = app.window();
        await("the window", window::isShowing);
        Dimension screen = onEdt(() -> window.getGraphicsConfiguration().getBounds().getSize());
        onEdt(() -> window.setBounds(0, 0, screen.width, screen.height));
        await("the large window laid out", () -> window.boardPanel().getHeight() > screen.height * 3 / 4);
        clickMenu(window.menus(), "Physics overlay");
        for (int i = 0; i < 30; i++) {
            onEdt(() -> app.loop().step());
        }
        assertBesideTheBoard(app, "overlay-large");
    }

    private static void assertBesideTheBoard(Gizmoball app, String shot) throws Exception {
        GameWindow window = app.window();
        BoardPanel panel = window.boardPanel();
        PhysicsOverlay overlay = app.playFeatures().physicsOverlay();
        PhysicsOverlay.Layout layout = onEdt(() -> {
            Graphics2D g = (Graphics2D) panel.getGraphics();
            try {
                g.setFont(PhysicsOverlay.FONT);
                return overlay.layout(g.getFontMetrics(), panel.transform(), overlay.shown());
            } finally {
                g.dispose();
            }
        });
        Rectangle2D board = onEdt(() -> panel.transform().board());

        Gui.sleep(300);
        Files.createDirectories(Path.of("build", "screenshots"));
        ImageIO.write(new Robot().createScreenCapture(onEdt(() -> window.getBounds())), "png",
                Path.of("build", "screenshots", shot + ".png").toFile());
        assertThat(layout.panel().intersects(board)).as("panel " + layout.panel() + " over the board " + board)
                .isFalse();
        assertThat(onEdt(() -> new Rectangle(panel.getSize())).contains(layout.panel().getBounds())).isTrue();
    }
}
