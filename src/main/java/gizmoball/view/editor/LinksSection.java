package gizmoball.view.editor;

import static gizmoball.view.editor.PanelFields.constraints;

import gizmoball.boardfile.KeyCodes;
import gizmoball.boardfile.OrderWords;
import gizmoball.editor.Editor;
import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;

import java.awt.Dimension;
import java.awt.GridBagConstraints;
import javax.swing.DefaultListModel;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.ListSelectionModel;

/** The properties panel's list of the selection's connections and key bindings, each removable. */
final class LinksSection {
    /** One line of the list, with what removing it means. */
    private record Link(String text, Runnable remove) {
        @Override
        public String toString() {
            return text;
        }
    }

    private static final int ROWS = 5;

    private final Editor controller;
    private final DefaultListModel<Link> links = new DefaultListModel<>();
    private final JList<Link> linkList = new JList<>(links);
    private final JButton removeLink = new JButton("Remove");

    LinksSection(Editor controller) {
        this.controller = controller;
    }

    /** The connections from or to {@code name} and its key bindings; none for null (nothing, or several, selected). */
    void show(Board board, String name) {
        links.clear();
        if (name != null) {
            for (Connection c : board.connections()) {
                if (c.source().equals(TriggerSource.named(name)) || c.target().equals(name)) {
                    links.addElement(new Link(c.source() + " \u2192 " + c.target() + OrderWords.of(c.order()),
                            () -> controller.properties().disconnect(c.source(), c.target())));
                }
            }
            for (KeyBinding k : board.keyBindings()) {
                if (k.gizmo().equals(name)) {
                    links.addElement(new Link(KeyCodes.describe(k), () -> controller.properties().unbind(k)));
                }
            }
        }
        removeLink.setEnabled(!links.isEmpty());
    }

    /** Adds its title, list and Remove button to the panel's grid, from row {@code first} on. */
    void addTo(JPanel p, int first) {
        GridBagConstraints l = constraints(0, first);
        l.gridwidth = 2;
        p.add(new JLabel("Connections and keys"), l);
        linkList.setName("links");
        linkList.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        // Rows as tall empty as full, so that the list is the same height whatever is selected (a flipper's two keys
        // and a connection or three fit); more scroll within it, so that the tab fits the window as it opens.
        linkList.setFixedCellHeight(linkList.getFontMetrics(linkList.getFont()).getHeight() + 2);   // + its border
        linkList.setVisibleRowCount(ROWS);
        JScrollPane scroll = new JScrollPane(linkList);
        scroll.setPreferredSize(new Dimension(200, scroll.getPreferredSize().height));
        // Never squeezed to a row: the panel scrolls instead (see gizmoball.app.BuildModeInstaller).
        scroll.setMinimumSize(scroll.getPreferredSize());
        GridBagConstraints s = constraints(0, first + 1);
        s.gridwidth = 2;
        s.fill = GridBagConstraints.BOTH;
        p.add(scroll, s);
        removeLink.setName("links.remove");
        removeLink.setToolTipText("Remove the chosen connection or key binding");
        removeLink.addActionListener(e -> {
            Link chosen = linkList.getSelectedValue();
            if (chosen != null) {
                chosen.remove().run();
            }
        });
        p.add(removeLink, constraints(1, first + 2));
    }
}
