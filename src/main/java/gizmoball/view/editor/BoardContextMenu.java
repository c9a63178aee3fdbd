package gizmoball.view.editor;

import gizmoball.editor.Editor;
import gizmoball.editor.PendingStep;
import gizmoball.view.BoardPanel;
import java.awt.event.MouseEvent;
import java.util.Locale;
import javax.swing.JMenuItem;
import javax.swing.JPopupMenu;
import physics.Vect;

/**
 * The board's context menu in build mode (right-click): what can be done to the gizmo or ball under the pointer,
 * which it selects (rotate, delete, cut, copy, duplicate, connect from here, its properties), and paste. A
 * right-click while a step is under way cancels the step instead, as Esc does.
 */
public final class BoardContextMenu {
    private final Editor controller;
    private final BoardPanel panel;
    private final JPopupMenu menu = new JPopupMenu();
    private final JMenuItem rotate;
    private final JMenuItem[] onSelection;

    /** @param showProperties brings the selection's properties to the keyboard (its name field) */
    public BoardContextMenu(Editor controller, BoardPanel panel, Runnable showProperties) {
        this.controller = controller;
        this.panel = panel;
        menu.setName("board.context");
        rotate = item("Rotate", controller::rotateSelected);
        JMenuItem delete = item("Delete", controller::deleteSelected);
        menu.addSeparator();
        JMenuItem cut = item("Cut", () -> controller.clipboard().cutSelected().ifPresent(Clipboard::put));
        JMenuItem copy = item("Copy", () -> controller.clipboard().copySelected().ifPresent(Clipboard::put));
        item("Paste", () -> controller.clipboard().paste(Clipboard.text()));
        JMenuItem duplicate = item("Duplicate", controller.clipboard()::duplicateSelected);
        menu.addSeparator();
        JMenuItem connect = item("Connect from here", controller::connectFromSelected);
        JMenuItem properties = item("Properties", showProperties);
        onSelection = new JMenuItem[] {delete, cut, copy, duplicate, connect, properties};
    }

    /** A right-click at the event's point: cancels a step under way, or selects and shows the menu there. */
    public void open(MouseEvent e) {
        if (!(controller.step() instanceof PendingStep.None)) {
            controller.cancel();
            return;
        }
        Vect at = panel.transform().toBoard(e.getX(), e.getY());
        boolean selected = controller.selectAt(at.x(), at.y());
        for (JMenuItem item : onSelection) {
            item.setEnabled(selected);
        }
        rotate.setEnabled(controller.selection().stream().anyMatch(n -> controller.board().gizmo(n).isPresent()));
        menu.show(panel, e.getX(), e.getY());
    }

    JPopupMenu menu() {
        return menu;
    }

    private JMenuItem item(String text, Runnable action) {
        JMenuItem item = new JMenuItem(text);
        item.setName("context." + text.replaceAll("\\W", "").toLowerCase(Locale.ROOT));
        item.addActionListener(ev -> action.run());
        menu.add(item);
        return item;
    }
}
