package gizmoball.view.editor;

import java.awt.Component;
import java.awt.Dimension;
import javax.swing.JComponent;
import javax.swing.JTabbedPane;

/**
 * The properties panel's two tabs, the board's and the selection's, one shown at a time so that the panel fits the
 * window as it opens (issue 40): stacked, the two were taller than it. As tall as the tab shown, not as the tallest
 * (Swing's own measure): the board's few rows then need no scroll bar in a window too short for the selection's.
 */
final class PanelTabs extends JTabbedPane {
    private static final int BOARD = 0;
    private static final int SELECTION = 1;

    PanelTabs(JComponent board, JComponent selection) {
        setName("properties.tabs");
        addTab("Board", board);
        setToolTipTextAt(BOARD, "Gravity, friction and the game's rules");
        addTab("Selection", selection);
        setToolTipTextAt(SELECTION, "What is selected on the board: its values, connections and keys");
        addChangeListener(e -> revalidate());
    }

    /** Brings the selection's tab forward, or the board's when nothing is selected. */
    void showSelection(boolean selection) {
        setSelectedIndex(selection ? SELECTION : BOARD);
    }

    @Override
    public Dimension getPreferredSize() {
        Dimension all = super.getPreferredSize();
        Component shown = getSelectedComponent();
        if (shown == null) {
            return all;
        }
        int tallest = 0;
        for (int i = 0; i < getTabCount(); i++) {
            tallest = Math.max(tallest, getComponentAt(i).getPreferredSize().height);
        }
        return new Dimension(all.width, all.height - tallest + shown.getPreferredSize().height);
    }
}
