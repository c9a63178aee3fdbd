package gizmoball.view.editor;

import gizmoball.editor.EdgeChoice;
import gizmoball.editor.Editor;
import gizmoball.view.BoardPanel;

import javax.swing.JMenuItem;
import javax.swing.JPopupMenu;
import javax.swing.event.PopupMenuEvent;
import javax.swing.event.PopupMenuListener;
import java.awt.geom.Point2D;

/**
 * Key Connect's last step: a popup next to the gizmo asks whether the binding acts on key down or key up.
 * The arrow keys answer too (the controller takes them); the popup closes whenever no answer is awaited.
 */
public final class EdgePopup {
    private final Editor controller;
    private final BoardPanel panel;
    private final JPopupMenu popup = new JPopupMenu("Key edge");

    private EdgePopup(Editor controller, BoardPanel panel) {
        this.controller = controller;
        this.panel = panel;
        popup.add(item("On key down and up (hold)", "edge.both", EdgeChoice.DOWN_AND_UP));
        popup.add(item("On key down (press)  \u2193", "edge.down", EdgeChoice.DOWN));
        popup.add(item("On key up (release)  \u2191", "edge.up", EdgeChoice.UP));
        popup.addPopupMenuListener(new PopupMenuListener() {
            @Override
            public void popupMenuWillBecomeVisible(PopupMenuEvent e) {
                // nothing to prepare
            }

            @Override
            public void popupMenuWillBecomeInvisible(PopupMenuEvent e) {
                // an answer, or a cancel handled below
            }

            @Override
            public void popupMenuCanceled(PopupMenuEvent e) {
                if (controller.awaitingEdge()) {
                    controller.cancel();
                }
            }
        });
    }

    /** The popup of {@code controller}'s Key Connect over {@code panel}, closing whenever no answer is awaited. */
    public static EdgePopup of(Editor controller, BoardPanel panel) {
        EdgePopup edges = new EdgePopup(controller, panel);
        controller.addStateListener(() -> {
            if (!controller.awaitingEdge() && edges.popup.isVisible()) {
                edges.popup.setVisible(false);
            }
        });
        return edges;
    }

    /** Shows the popup at the top-right corner of the selected gizmo (or mid-board). */
    public void show() {
        Point2D at = controller.selectedGizmo()
                .map(g -> panel.transform().toScreen(g.x() + g.width(), g.y()))
                .orElse(new Point2D.Double(panel.getWidth() / 2.0, panel.getHeight() / 2.0));
        popup.show(panel, (int) at.getX(), (int) at.getY());
        // Keys keep going to the board (arrow keys answer, Escape cancels).
        panel.requestFocusInWindow();
    }

    private JMenuItem item(String text, String name, EdgeChoice edge) {
        JMenuItem item = new JMenuItem(text);
        item.setName(name);
        item.addActionListener(e -> controller.chooseEdges(edge));
        return item;
    }
}
