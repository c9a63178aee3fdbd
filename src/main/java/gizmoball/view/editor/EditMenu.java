package gizmoball.view.editor;

import gizmoball.editor.Editor;

import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.KeyStroke;
import java.awt.Component;

import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.util.function.BooleanSupplier;

/**
 * Edit menu of build mode: Undo and Redo (each saying what it would take back or bring again), Rotate and Delete
 * selection, Cut, Copy, Paste and Duplicate (enabled only when there is a selection they act on), Clear board
 * (after confirmation).
 */
public final class EditMenu extends JMenu {
    private final Editor controller;
    private final BooleanSupplier building;
    private final JMenuItem undo;
    private final JMenuItem redo;
    private final JMenuItem rotate;
    private final JMenuItem delete;
    private final JMenuItem cut;
    private final JMenuItem copy;
    private final JMenuItem duplicate;

    private EditMenu(Editor controller, Component parent, BooleanSupplier building) {
        super("Edit");
        this.controller = controller;
        this.building = building;
        setMnemonic(KeyEvent.VK_E);
        undo = item("Undo", KeyStroke.getKeyStroke(KeyEvent.VK_Z, InputEvent.CTRL_DOWN_MASK), controller::undo);
        redo = item("Redo", KeyStroke.getKeyStroke(KeyEvent.VK_Y, InputEvent.CTRL_DOWN_MASK), controller::redo);
        addSeparator();
        // No accelerator: Ctrl+R is the File menu's Reload.
        rotate = item("Rotate selection", null, controller::rotateSelected);
        delete = item("Delete selection", null, controller::deleteSelected);
        delete.setToolTipText("Also the Delete key over the board");
        addSeparator();
        // The clipboard holds board-file lines: they paste into another window, or into a text editor.
        cut = item("Cut", KeyStroke.getKeyStroke(KeyEvent.VK_X, InputEvent.CTRL_DOWN_MASK),
                () -> controller.clipboard().cutSelected().ifPresent(Clipboard::put));
        copy = item("Copy", KeyStroke.getKeyStroke(KeyEvent.VK_C, InputEvent.CTRL_DOWN_MASK),
                () -> controller.clipboard().copySelected().ifPresent(Clipboard::put));
        item("Paste", KeyStroke.getKeyStroke(KeyEvent.VK_V, InputEvent.CTRL_DOWN_MASK),
                () -> controller.clipboard().paste(Clipboard.text()));
        duplicate = item("Duplicate", KeyStroke.getKeyStroke(KeyEvent.VK_D, InputEvent.CTRL_DOWN_MASK),
                controller.clipboard()::duplicateSelected);
        addSeparator();
        item("Clear board\u2026", null, () -> {
            int answer = JOptionPane.showConfirmDialog(parent,
                    "Remove every gizmo, ball, connection and key binding, and reset gravity and friction?\n"
                            + "(Edit > Undo brings them back.)", "Clear board", JOptionPane.OK_CANCEL_OPTION,
                    JOptionPane.WARNING_MESSAGE);
            if (answer == JOptionPane.OK_OPTION) {
                controller.clearBoard();
            }
        });
        update();
    }

    /** The Edit menu of {@code controller}, following its history and selection. */
    public static EditMenu of(Editor controller, Component parent, BooleanSupplier building) {
        EditMenu menu = new EditMenu(controller, parent, building);
        controller.history().addListener(menu::update);
        controller.addStateListener(menu::update);
        return menu;
    }

    /** Enables the menu in build mode only, and Undo/Redo only when there is something to undo or redo. */
    public void update() {
        boolean on = building.getAsBoolean();
        setEnabled(on);
        undo.setEnabled(on && controller.history().canUndo());
        redo.setEnabled(on && controller.history().canRedo());
        undo.setText(controller.history().undoable().map(what -> "Undo: " + what).orElse("Undo"));
        redo.setText(controller.history().redoable().map(what -> "Redo: " + what).orElse("Redo"));
        boolean something = !controller.selection().isEmpty();
        rotate.setEnabled(on && controller.selection().stream().anyMatch(n -> controller.board().gizmo(n).isPresent()));
        delete.setEnabled(on && something);
        cut.setEnabled(on && something);
        copy.setEnabled(on && something);
        duplicate.setEnabled(on && something);
    }


    private JMenuItem item(String text, KeyStroke accelerator, Runnable action) {
        JMenuItem item = new JMenuItem(text);
        item.setName("edit." + text.replaceAll("\\W", "").toLowerCase());
        item.setAccelerator(accelerator);
        item.addActionListener(e -> action.run());
        add(item);
        return item;
    }
}
