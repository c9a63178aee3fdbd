package gizmoball.view.editor;

import gizmoball.editor.Editor;
import gizmoball.view.BoardPanel;
import physics.Vect;

import javax.swing.SwingUtilities;
import java.awt.event.KeyEvent;
import java.awt.event.KeyListener;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;

/**
 * Turns mouse and key events on the board view into {@link Editor} calls in board coordinates.
 * It listens all the time but acts only while {@code active} says so (build mode): play mode keeps the keys.
 */
public final class BoardInput extends MouseAdapter implements KeyListener {
    private final Editor controller;
    private final BoardPanel panel;
    private final BooleanSupplier active;
    private final Runnable chooseEdge;
    private final Consumer<MouseEvent> contextMenu;

    /**
     * @param chooseEdge  asked to let the user pick the action (and for Key Connect down or up) once Key Connect has
     *                    its key or Connect its target (e.g. a popup menu)
     * @param contextMenu a right-click (it cancels a step under way, or opens the board's context menu)
     */
    private BoardInput(Editor controller, BoardPanel panel, BooleanSupplier active, Runnable chooseEdge,
                       Consumer<MouseEvent> contextMenu) {
        this.controller = controller;
        this.panel = panel;
        this.active = active;
        this.chooseEdge = chooseEdge;
        this.contextMenu = contextMenu;
    }

    public static BoardInput attach(Editor controller, BoardPanel panel, BooleanSupplier active,
                                    Runnable chooseEdge, Consumer<MouseEvent> contextMenu) {
        BoardInput input = new BoardInput(controller, panel, active, chooseEdge, contextMenu);
        panel.addMouseListener(input);
        panel.addMouseMotionListener(input);
        panel.addKeyListener(input);
        panel.setFocusable(true);
        return input;
    }

    @Override
    public void mousePressed(MouseEvent e) {
        if (!active.getAsBoolean()) {
            return;
        }
        // Keys (tool shortcuts, Key Connect) go to the board once the author works on it.
        panel.requestFocusInWindow();
        if (SwingUtilities.isLeftMouseButton(e)) {
            Vect p = toBoard(e);
            controller.press(p.x(), p.y(), e.isShiftDown());
            afterKeyOrClick();
        } else if (SwingUtilities.isRightMouseButton(e)) {
            contextMenu.accept(e);
        }
    }

    @Override
    public void mouseDragged(MouseEvent e) {
        if (active.getAsBoolean() && SwingUtilities.isLeftMouseButton(e)) {
            Vect p = toBoard(e);
            controller.drag(p.x(), p.y());
        }
    }

    @Override
    public void mouseReleased(MouseEvent e) {
        if (active.getAsBoolean() && SwingUtilities.isLeftMouseButton(e)) {
            Vect p = toBoard(e);
            controller.release(p.x(), p.y());
        }
    }

    @Override
    public void mouseMoved(MouseEvent e) {
        if (active.getAsBoolean()) {
            Vect p = toBoard(e);
            controller.hover(p.x(), p.y());
        }
    }

    @Override
    public void mouseExited(MouseEvent e) {
        if (active.getAsBoolean()) {
            controller.exit();
        }
    }

    @Override
    public void keyPressed(KeyEvent e) {
        if (!active.getAsBoolean()) {
            return;
        }
        boolean command = e.isControlDown() || e.isAltDown() || e.isMetaDown();
        if (controller.keyPressed(e.getKeyCode(), command)) {
            e.consume();
            afterKeyOrClick();
        }
    }

    @Override
    public void keyReleased(KeyEvent e) {
        // Bindings are made on press; the edge (down/up) is chosen explicitly.
    }

    @Override
    public void keyTyped(KeyEvent e) {
        // Key codes, not characters, are what key connections use.
    }

    private void afterKeyOrClick() {
        if (controller.awaitingEdge() || controller.awaitingAction()) {
            chooseEdge.run();
        }
    }

    private Vect toBoard(MouseEvent e) {
        return panel.transform().toBoard(e.getX(), e.getY());
    }
}
