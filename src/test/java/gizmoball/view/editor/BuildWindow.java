package gizmoball.view.editor;

import gizmoball.app.BuildModeInstaller;
import gizmoball.app.Gizmoball;
import gizmoball.session.GameSession;
import gizmoball.session.Mode;
import gizmoball.editor.Tool;
import gizmoball.model.Board;
import gizmoball.view.BoardPanel;
import gizmoball.view.GameWindow;
import gizmoball.view.Gui;

import java.awt.Component;
import javax.swing.JToggleButton;
import java.awt.Point;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.KeyListener;
import java.awt.event.MouseEvent;
import java.awt.geom.Point2D;
import java.util.List;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;

/**
 * A game window with build mode installed and switched on, and the gestures of a board author: palette
 * clicks, and mouse events delivered to the board view at the pixels of board points, as AWT would.
 */
final class BuildWindow {
    final GameWindow window;
    final BuildModeInstaller.BuildMode build;
    final GameSession session;
    final Board board;
    final BoardPanel panel;

    private BuildWindow() {
        Gizmoball app = Gizmoball.launch(null);
        window = app.window();
        build = app.build();
        session = app.session();
        board = session.board();
        panel = window.boardPanel();
        onEdt(() -> session.setMode(Mode.BUILD));
        await("the board view is laid out", () -> panel.isShowing() && panel.getWidth() > 100);
    }

    /** Opens one (skipping the test, with the reason, when there is no display). */
    static BuildWindow open() {
        Gui.assumeDisplay();
        return new BuildWindow();
    }

    void close() {
        onEdt(window::dispose);
    }

    void clickTool(Tool tool) {
        onEdt(() -> toolButton(tool).doClick(0));
    }

    /** The palette's button of a tool, found by its component name. */
    JToggleButton toolButton(Tool tool) {
        return onEdt(() -> EditorGui.find(build.palette(), JToggleButton.class, "tool." + tool.name()));
    }

    void clickCell(int cx, int cy) {
        click(cx + 0.5, cy + 0.5);
    }

    void click(double x, double y) {
        onEdt(() -> {
            mouse(MouseEvent.MOUSE_PRESSED, x, y);
            mouse(MouseEvent.MOUSE_RELEASED, x, y);
        });
    }

    /** A click with Shift held (adds to the selection or takes out of it). */
    void shiftClick(double x, double y) {
        onEdt(() -> {
            mouse(MouseEvent.MOUSE_PRESSED, x, y, InputEvent.SHIFT_DOWN_MASK);
            mouse(MouseEvent.MOUSE_RELEASED, x, y, InputEvent.SHIFT_DOWN_MASK);
        });
    }

    /** The pointer moves over the board to (x, y) with no button down. */
    void hover(double x, double y) {
        onEdt(() -> {
            Point2D p = panel.transform().toScreen(x, y);
            panel.dispatchEvent(new MouseEvent(panel, MouseEvent.MOUSE_MOVED, System.currentTimeMillis(), 0,
                    (int) Math.round(p.getX()), (int) Math.round(p.getY()), 0, false, MouseEvent.NOBUTTON));
        });
    }

    void dragCells(int x0, int y0, int x1, int y1) {
        drag(x0 + 0.5, y0 + 0.5, x1 + 0.5, y1 + 0.5);
    }

    void drag(double x0, double y0, double x1, double y1) {
        onEdt(() -> {
            mouse(MouseEvent.MOUSE_PRESSED, x0, y0);
            mouse(MouseEvent.MOUSE_DRAGGED, (x0 + x1) / 2, (y0 + y1) / 2);
            mouse(MouseEvent.MOUSE_DRAGGED, x1, y1);
            mouse(MouseEvent.MOUSE_RELEASED, x1, y1);
        });
    }

    /** A key press handed to the board view's key listeners (no window focus needed on a bare X server). */
    void key(int keyCode) {
        onEdt(() -> {
            KeyEvent e = new KeyEvent(panel, KeyEvent.KEY_PRESSED, System.currentTimeMillis(), 0, keyCode,
                    KeyEvent.CHAR_UNDEFINED);
            List.of(panel.getKeyListeners()).forEach((KeyListener l) -> l.keyPressed(e));
        });
    }

    String status() {
        return onEdt(() -> window.statusLine().message());
    }

    /** Screen position of the middle of a board cell, for java.awt.Robot. */
    Point cellOnScreen(int cx, int cy) {
        return onEdt(() -> {
            Point2D p = panel.transform().toScreen(cx + 0.5, cy + 0.5);
            Point origin = panel.getLocationOnScreen();
            return new Point(origin.x + (int) Math.round(p.getX()), origin.y + (int) Math.round(p.getY()));
        });
    }

    static Point centreOnScreen(Component c) {
        return onEdt(() -> {
            Point origin = c.getLocationOnScreen();
            return new Point(origin.x + c.getWidth() / 2, origin.y + c.getHeight() / 2);
        });
    }

    private void mouse(int id, double x, double y) {
        mouse(id, x, y, 0);
    }

    private void mouse(int id, double x, double y, int keys) {
        Point2D p = panel.transform().toScreen(x, y);
        int modifiers = keys | (id == MouseEvent.MOUSE_RELEASED ? 0 : InputEvent.BUTTON1_DOWN_MASK);
        int clicks = id == MouseEvent.MOUSE_DRAGGED ? 0 : 1;
        panel.dispatchEvent(new MouseEvent(panel, id, System.currentTimeMillis(), modifiers,
                (int) Math.round(p.getX()), (int) Math.round(p.getY()), clicks, false, MouseEvent.BUTTON1));
    }
}
