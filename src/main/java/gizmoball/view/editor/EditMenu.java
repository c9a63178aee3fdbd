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

/** Edit menu of build mode: Undo, Redo, Rotate and Delete selection, Clear board (after confirmation). */
public final class EditMenu extends JMenu {
    private final Editor controller;
    private final BooleanSupplier building;
    private final JMenuItem undo;
    private final JMenuItem redo;

    public EditMenu(Editor controller, Component parent, BooleanSupplier building) {
        super("Edit");
        this.controller = controller;
        this.building = building;
        setMnemonic(KeyEvent.VK_E);
        undo = item("Undo", KeyStroke.getKeyStroke(KeyEvent.VK_Z, InputEvent.CTRL_DOWN_MASK), controller::undo);
        redo = item("Redo", KeyStroke.getKeyStroke(KeyEvent.VK_Y, InputEvent.CTRL_DOWN_MASK), controller::redo);
        addSeparator();
        // No accelerator: Ctrl+R is the File menu's Reload.
        item("Rotate selection", null, controller::rotateSelected);
        item("Delete selection", null, controller::deleteSelected).setToolTipText("Also the Delete key over the board");
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
        controller.history().addListener(this::update);
        update();
    }

    /** Enables the menu in build mode only, and Undo/Redo only when there is something to undo or redo. */
    public void update() {
        boolean on = building.getAsBoolean();
        setEnabled(on);
        undo.setEnabled(on && controller.history().canUndo());
        redo.setEnabled(on && controller.history().canRedo());
        undo.setToolTipText(controller.history().undoable().map(what -> "Undo: " + what).orElse(null));
        redo.setToolTipText(controller.history().redoable().map(what -> "Redo: " + what).orElse(null));
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
