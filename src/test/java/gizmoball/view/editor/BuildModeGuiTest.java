package gizmoball.view.editor;

import gizmoball.controller.GameSession;
import gizmoball.controller.Mode;
import gizmoball.controller.editor.Design;
import gizmoball.controller.editor.Tool;
import gizmoball.model.Board;
import gizmoball.model.Connection;
import gizmoball.model.Flipper;
import gizmoball.model.Gizmo;
import gizmoball.model.GizmoKind;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.view.BoardPanel;
import gizmoball.view.GameWindow;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import javax.swing.JList;
import javax.swing.JMenuItem;
import javax.swing.JTextField;
import java.awt.Point;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.KeyListener;
import java.awt.event.MouseEvent;
import java.awt.geom.Point2D;
import java.util.ArrayList;
import java.util.List;

import static gizmoball.view.editor.EditorGui.await;
import static gizmoball.view.editor.EditorGui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

/**
 * Build mode in a real window (under Xvfb in CI): palette buttons are clicked, mouse events arrive at the
 * board view at the pixels of board cells, keys go through the board view's key listener, menus are clicked.
 * One test drives the real pointer with java.awt.Robot. Skipped, with the reason, without a display.
 */
class BuildModeGuiTest {
    private GameWindow window;
    private BuildModeInstaller.BuildMode build;
    private GameSession session;
    private Board board;
    private BoardPanel panel;

    @BeforeEach
    void openWindowInBuildMode() {
        EditorGui.assumeDisplay();
        window = GameWindow.launch(null);
        build = onEdt(() -> BuildModeInstaller.install(window));
        session = window.session();
        board = session.board();
        panel = window.boardPanel();
        onEdt(() -> session.setMode(Mode.BUILD));
        await("the board view is laid out", () -> panel.isShowing() && panel.getWidth() > 100);
    }

    @AfterEach
    void close() {
        if (window != null) {
            onEdt(window::dispose);
        }
    }

    @Test
    void robotClicksOnThePaletteAndTheBoardPlaceASquare() throws Exception {
        Robot robot = new Robot();
        robot.setAutoDelay(20);
        Point button = onEdt(() -> centreOnScreen(build.palette().button(Tool.SQUARE)));
        Point cell = onEdt(() -> cellOnScreen(6, 9));
        robot.mouseMove(button.x, button.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        await("the Square tool is chosen", () -> build.controller().tool() == Tool.SQUARE);
        robot.mouseMove(cell.x, cell.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);

        await("S1 is on the board", () -> board.gizmo("S1").isPresent());
        Gizmo s1 = board.gizmo("S1").orElseThrow();
        assertThat(List.of(s1.x(), s1.y())).containsExactly(6, 9);
        assertThat(session.isModified()).isTrue();
    }

    @Test
    void everyKindIsPlacedByClickingItsToolAndTheBoard() {
        clickTool(Tool.SQUARE);
        clickCell(1, 1);
        clickTool(Tool.CIRCLE);
        clickCell(3, 1);
        clickTool(Tool.TRIANGLE);
        clickCell(5, 1);
        clickTool(Tool.LEFT_FLIPPER);
        clickCell(1, 5);
        clickTool(Tool.RIGHT_FLIPPER);
        clickCell(5, 5);
        clickTool(Tool.ABSORBER);
        dragCells(0, 19, 19, 19);
        clickTool(Tool.BALL);
        onEdt(() -> mouse(MouseEvent.MOUSE_PRESSED, 10.5, 10.5));
        onEdt(() -> mouse(MouseEvent.MOUSE_DRAGGED, 11.5, 8.5));
        onEdt(() -> mouse(MouseEvent.MOUSE_RELEASED, 11.5, 8.5));

        assertThat(onEdt(() -> board.gizmos().stream().map(Gizmo::kind).toList())).containsExactly(
                GizmoKind.SQUARE, GizmoKind.CIRCLE, GizmoKind.TRIANGLE, GizmoKind.LEFT_FLIPPER,
                GizmoKind.RIGHT_FLIPPER, GizmoKind.ABSORBER);
        Gizmo absorber = board.gizmo("A1").orElseThrow();
        assertThat(List.of(absorber.x(), absorber.y(), absorber.width(), absorber.height()))
                .containsExactly(0, 19, 20, 1);
        // A drag of (+1, -2) L from the ball's centre gives (10, -20) L/s at 10 L/s per L dragged.
        var ball = board.ball("B1").orElseThrow();
        assertThat(ball.position().x()).isCloseTo(10.5, within(1e-9));
        assertThat(ball.velocity().x()).isCloseTo(10, within(1e-9));
        assertThat(ball.velocity().y()).isCloseTo(-20, within(1e-9));
        assertThat(session.isModified()).isTrue();
    }

    @Test
    void draggingAGizmoMovesItAndRotateAndDeleteActOnTheClickedGizmo() {
        clickTool(Tool.TRIANGLE);
        clickCell(2, 2);
        clickTool(Tool.SELECT);
        dragCells(2, 2, 12, 7);
        assertThat(onEdt(() -> List.of(board.gizmo("T1").orElseThrow().x(), board.gizmo("T1").orElseThrow().y())))
                .containsExactly(12, 7);

        clickTool(Tool.ROTATE);
        clickCell(12, 7);
        assertThat(board.gizmo("T1").orElseThrow().rotation()).isEqualTo(1);

        clickTool(Tool.DELETE);
        clickCell(12, 7);
        assertThat(board.gizmos()).isEmpty();
    }

    @Test
    void connectingTwoGizmosShowsTheConnectionInTheProperties() {
        clickTool(Tool.CIRCLE);
        clickCell(4, 4);
        clickTool(Tool.LEFT_FLIPPER);
        clickCell(8, 8);
        clickTool(Tool.CONNECT);
        clickCell(4, 4);
        clickCell(9, 9);

        assertThat(board.connections()).containsExactly(new Connection("C1", "LF1"));
        JList<?> links = onEdt(() -> EditorGui.find(build.properties(), JList.class, "links"));
        assertThat(onEdt(() -> links.getModel().getSize())).isEqualTo(1);
        assertThat(onEdt(() -> links.getModel().getElementAt(0).toString())).isEqualTo("C1 \u2192 LF1");
    }

    @Test
    void aKeyBoundInBuildModeSwingsTheFlipperInPlay() {
        clickTool(Tool.LEFT_FLIPPER);
        clickCell(3, 15);
        clickTool(Tool.KEY_CONNECT);
        clickCell(3, 15);
        onEdt(() -> key(KeyEvent.VK_SPACE));
        JMenuItem down = onEdt(() -> EditorGui.showingMenuItem("edge.down"));
        onEdt(() -> down.doClick(0));

        assertThat(board.keyBindings()).containsExactly(new KeyBinding(KeyEvent.VK_SPACE, KeyEdge.DOWN, "LF1"));
        onEdt(() -> session.setMode(Mode.PLAY));
        onEdt(() -> {
            board.keyDown(KeyEvent.VK_SPACE);
            board.tick(0.1);
        });
        Flipper lf1 = (Flipper) board.gizmo("LF1").orElseThrow();
        assertThat(lf1.angleFromRest()).isCloseTo(90, within(1e-9));
    }

    @Test
    void undoAndRedoFromTheEditMenu() {
        clickTool(Tool.SQUARE);
        clickCell(1, 1);
        clickCell(2, 1);
        JMenuItem undo = onEdt(() -> EditorGui.menuItem(window.menus(), "Undo"));
        JMenuItem redo = onEdt(() -> EditorGui.menuItem(window.menus(), "Redo"));
        assertThat(onEdt(redo::isEnabled)).isFalse();

        onEdt(() -> undo.doClick(0));
        assertThat(board.gizmos()).extracting(Gizmo::name).containsExactly("S1");
        assertThat(onEdt(redo::isEnabled)).isTrue();
        onEdt(() -> redo.doClick(0));
        assertThat(board.gizmos()).extracting(Gizmo::name).containsExactly("S1", "S2");
    }

    @Test
    void aRefusedOverlapLeavesTheBoardAsItWasAndSaysWhyOnTheStatusLine() {
        clickTool(Tool.SQUARE);
        clickCell(5, 5);
        Design before = onEdt(() -> Design.of(board));
        clickTool(Tool.RIGHT_FLIPPER);
        clickCell(4, 4);

        assertThat(onEdt(() -> Design.of(board))).isEqualTo(before);
        assertThat(onEdt(() -> window.statusLine().message())).contains("overlap").contains("S1");
    }

    @Test
    void gravityTypedIntoThePropertiesIsValidated() {
        JTextField gravity = onEdt(() -> EditorGui.find(build.properties(), JTextField.class, "gravity"));
        onEdt(() -> {
            gravity.setText("strong");
            gravity.postActionEvent();
        });
        assertThat(board.gravity()).isEqualTo(Board.DEFAULT_GRAVITY);
        assertThat(onEdt(() -> window.statusLine().message())).contains("not a number");

        onEdt(() -> {
            gravity.setText("10");
            gravity.postActionEvent();
        });
        assertThat(board.gravity()).isEqualTo(10);
    }

    @Test
    void inPlayModeTheMouseDoesNotEdit() {
        clickTool(Tool.SQUARE);
        onEdt(() -> session.setMode(Mode.PLAY));
        clickCell(3, 3);
        assertThat(board.gizmos()).isEmpty();
        assertThat(onEdt(build.editMenu()::isEnabled)).isFalse();
    }

    // ---- helpers: events at the pixels of board points ----

    private void clickTool(Tool tool) {
        onEdt(() -> build.palette().button(tool).doClick(0));
    }

    private void clickCell(int cx, int cy) {
        onEdt(() -> {
            mouse(MouseEvent.MOUSE_PRESSED, cx + 0.5, cy + 0.5);
            mouse(MouseEvent.MOUSE_RELEASED, cx + 0.5, cy + 0.5);
        });
    }

    private void dragCells(int x0, int y0, int x1, int y1) {
        onEdt(() -> {
            mouse(MouseEvent.MOUSE_PRESSED, x0 + 0.5, y0 + 0.5);
            mouse(MouseEvent.MOUSE_DRAGGED, (x0 + x1) / 2.0 + 0.5, (y0 + y1) / 2.0 + 0.5);
            mouse(MouseEvent.MOUSE_DRAGGED, x1 + 0.5, y1 + 0.5);
            mouse(MouseEvent.MOUSE_RELEASED, x1 + 0.5, y1 + 0.5);
        });
    }

    /** A left-button mouse event at board point (x, y), delivered to the board view as AWT would. */
    private void mouse(int id, double x, double y) {
        Point2D p = panel.transform().toScreen(x, y);
        int modifiers = id == MouseEvent.MOUSE_RELEASED ? 0 : InputEvent.BUTTON1_DOWN_MASK;
        int clicks = id == MouseEvent.MOUSE_DRAGGED ? 0 : 1;
        panel.dispatchEvent(new MouseEvent(panel, id, System.currentTimeMillis(), modifiers,
                (int) Math.round(p.getX()), (int) Math.round(p.getY()), clicks, false, MouseEvent.BUTTON1));
    }

    /** A key press handed to the board view's key listeners (no window focus needed on a bare X server). */
    private void key(int keyCode) {
        KeyEvent e = new KeyEvent(panel, KeyEvent.KEY_PRESSED, System.currentTimeMillis(), 0, keyCode,
                KeyEvent.CHAR_UNDEFINED);
        List<KeyListener> listeners = new ArrayList<>(List.of(panel.getKeyListeners()));
        listeners.forEach(l -> l.keyPressed(e));
    }

    private Point cellOnScreen(int cx, int cy) {
        Point2D p = panel.transform().toScreen(cx + 0.5, cy + 0.5);
        Point origin = panel.getLocationOnScreen();
        return new Point(origin.x + (int) Math.round(p.getX()), origin.y + (int) Math.round(p.getY()));
    }

    private static Point centreOnScreen(java.awt.Component c) {
        Point origin = c.getLocationOnScreen();
        return new Point(origin.x + c.getWidth() / 2, origin.y + c.getHeight() / 2);
    }
}
