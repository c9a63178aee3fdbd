package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.clickMenu;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.app.Gizmoball;
import gizmoball.session.Mode;
import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.GizmoKind;
import java.awt.Component;
import java.awt.KeyboardFocusManager;
import java.awt.Point;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import javax.swing.JLabel;
import javax.swing.JToggleButton;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The window on a real board, driven through its menus, toolbar and the keyboard (needs a display). */
class GameWindowTest {
    private static final double DT = Board.DEFAULT_TICK;
    private static final int FLIPPER_KEY = KeyEvent.VK_Z;

    private Gizmoball app;
    private GameWindow window;

    @BeforeEach
    void open() {
        Gui.assumeDisplay();
        app = Gizmoball.launch(null);
        window = app.window();
        onEdt(() -> {
            Board board = new Board();
            board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 6, 15);
            board.addGizmo(GizmoKind.SQUARE, "S", 2, 2);
            board.addBall("B", 10.5, 5, 0, 0);
            board.bindKey(FLIPPER_KEY, KeyEdge.DOWN, "LF");
            board.bindKey(FLIPPER_KEY, KeyEdge.UP, "LF");
            window.session().load(board, null);
        });
    }

    @AfterEach
    void close() {
        if (window != null) {
            onEdt(window::dispose);
        }
    }

    private double time() {
        return onEdt(() -> window.session().board().time());
    }

    private FlipperView flipper() {
        return onEdt(() -> (FlipperView) window.session().board().gizmo("LF").orElseThrow());
    }

    @Test
    void tickStepsOneTickAtATimeWhileStopped() {
        clickMenu(window.menus(), "Tick");
        assertThat(time()).isEqualTo(DT);

        clickMenu(window.menus(), "Tick");
        clickMenu(window.menus(), "Tick");
        assertThat(time()).isCloseTo(3 * DT, within(1e-12));
    }

    @Test
    void startRunsTheClockAndStopHaltsIt() {
        clickMenu(window.menus(), "Start");
        await("simulated time to pass", () -> window.session().board().time() > 10 * DT);
        assertThat(onEdt(() -> Gui.menuItem(window.menus(), "Tick").isEnabled())).isFalse();

        clickMenu(window.menus(), "Stop");
        // A stopped loop sends itself no more ticks (GameLoopTest): that Stop stopped it is what is left to see.
        assertThat(onEdt(() -> app.loop().isRunning())).isFalse();
        assertThat(onEdt(() -> Gui.menuItem(window.menus(), "Tick").isEnabled())).isTrue();
    }

    @Test
    void theStatusLineShowsTheBoardItsStateAndTheSimulatedTime() {
        for (int i = 0; i < 3; i++) {
            clickMenu(window.menus(), "Tick");
        }
        await("the status line to show 3 ticks", () -> statusText().contains("t = 0.05 s"));
        assertThat(statusText()).contains("untitled", "Play - stopped");

        clickMenu(window.menus(), "Start");
        await("the status line to say running", () -> statusText().contains("Play - running"));
    }

    private String statusText() {
        return onEdt(() -> window.statusLine().text());
    }

    @Test
    void resetPutsTheBallBackWhereTheBoardStarted() {
        for (int i = 0; i < 20; i++) {
            clickMenu(window.menus(), "Tick");
        }
        assertThat(onEdt(() -> window.session().board().balls().get(0).position().y())).isGreaterThan(5);

        clickMenu(window.menus(), "Reset");

        assertThat(onEdt(() -> window.session().board().balls().get(0).position().y())).isEqualTo(5);
    }

    @Test
    void holdingTheBoundKeySwingsTheFlipperUpAndReleasingItSwingsItBack() throws Exception {
        focusBoard();
        Robot robot = new Robot();
        robot.setAutoDelay(10);

        robot.keyPress(FLIPPER_KEY);
        await("the flipper to go active", () -> flipper().isActive());
        for (int i = 0; i < 10; i++) {   // 1/6 s: more than the 1/12 s the 90 degree swing takes
            clickMenu(window.menus(), "Tick");
        }
        assertThat(flipper().angleFromRest()).isEqualTo(90);
        autoRepeat(FLIPPER_KEY, 5);
        clickMenu(window.menus(), "Tick");
        assertThat(onEdt(() -> window.session().board().lastTick().events())).as("swings while held").isEmpty();
        assertThat(flipper().isActive()).as("still held").isTrue();
        assertThat(flipper().angleFromRest()).isEqualTo(90);

        robot.keyRelease(FLIPPER_KEY);
        await("the flipper to be released", () -> !flipper().isActive());
        for (int i = 0; i < 10; i++) {
            clickMenu(window.menus(), "Tick");
        }
        assertThat(flipper().angleFromRest()).isZero();
    }

    /**
     * What X11 sends while a key is held: a release and a press together, again and again (the platform's
     * timing is not the test's business; {@code KeyRepeatFilterTest} covers the timing of the pairs).
     */
    private void autoRepeat(int keyCode, int times) {
        onEdt(() -> {
            Component focused = KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner();
            for (int i = 0; i < times; i++) {
                long when = System.currentTimeMillis();
                focused.dispatchEvent(new KeyEvent(focused, KeyEvent.KEY_RELEASED, when, 0, keyCode,
                        KeyEvent.CHAR_UNDEFINED));
                focused.dispatchEvent(new KeyEvent(focused, KeyEvent.KEY_PRESSED, when, 0, keyCode,
                        KeyEvent.CHAR_UNDEFINED));
            }
        });
    }

    @Test
    void buildModeStopsTheGameShowsTheGridAndHidesTheSidePanels() {
        JLabel west = new JLabel("palette");
        JLabel east = new JLabel("properties");
        onEdt(() -> window.setSidePanels(west, east));
        assertThat(onEdt(west::isVisible)).isFalse();
        clickMenu(window.menus(), "Start");

        onEdt(() -> Gui.find(window.toolBar(), JToggleButton.class, b -> "Build".equals(b.getText()))
                .orElseThrow().doClick(0));

        assertThat(onEdt(() -> window.session().mode())).isEqualTo(Mode.BUILD);
        assertThat(onEdt(west::isVisible)).isTrue();
        assertThat(onEdt(east::isVisible)).isTrue();
        assertThat(onEdt(() -> gridLineShows(window.boardPanel()))).as("the grid, in build mode").isTrue();
        assertThat(onEdt(() -> Gui.menuItem(window.menus(), "Start").isEnabled())).isFalse();
        assertThat(onEdt(() -> Gui.menuItem(window.menus(), "Build").isSelected())).isTrue();
        assertThat(onEdt(() -> app.loop().isRunning())).as("the game, in build mode").isFalse();

        clickMenu(window.menus(), "Play");
        assertThat(onEdt(west::isVisible)).isFalse();
        assertThat(onEdt(() -> Gui.menuItem(window.menus(), "Start").isEnabled())).isTrue();
    }

    @Test
    void theTitleMarksUnsavedChanges() {
        assertThat(onEdt(window::getTitle)).isEqualTo("Gizmoball - untitled");

        onEdt(() -> window.session().markModified());

        assertThat(onEdt(window::getTitle)).isEqualTo("Gizmoball - untitled *");
    }

    @Test
    void quitClosesTheWindowWhenNothingIsUnsaved() {
        clickMenu(window.menus(), "Quit");

        assertThat(onEdt(window::isDisplayable)).isFalse();
    }

    /** Clicks into the board so that the window has the keyboard focus (there is no window manager under Xvfb). */
    private void focusBoard() throws Exception {
        Robot robot = new Robot();
        Point centre = onEdt(() -> {
            Point p = window.boardPanel().getLocationOnScreen();
            return new Point(p.x + window.boardPanel().getWidth() / 2, p.y + window.boardPanel().getHeight() / 2);
        });
        robot.mouseMove(centre.x, centre.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        await("the board to have the keyboard focus", () -> window.boardPanel().isFocusOwner());
    }

    /** Whether the panel, painted now, shows a grid line at x = 15 L (the floor is plain there without one). */
    private static boolean gridLineShows(BoardPanel panel) {
        java.awt.image.BufferedImage image = new java.awt.image.BufferedImage(panel.getWidth(), panel.getHeight(),
                java.awt.image.BufferedImage.TYPE_INT_RGB);
        java.awt.Graphics2D g = image.createGraphics();
        panel.paint(g);
        g.dispose();
        java.awt.geom.Point2D line = panel.transform().toScreen(15, 5.5);
        return !new java.awt.Color(image.getRGB((int) line.getX(), (int) line.getY())).equals(BoardPainter.FLOOR);
    }
}
