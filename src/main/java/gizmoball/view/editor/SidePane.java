package gizmoball.view.editor;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Rectangle;
import javax.swing.JComponent;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.ScrollPaneConstants;
import javax.swing.Scrollable;

/**
 * A build-mode side (palette or properties) that scrolls vertically when the window is too short for it, so
 * that a small window keeps every tool and field in reach without the window being resized. The scroll bar is
 * always there (greyed when all fits), so the board view never shifts when the window's height changes.
 */
public final class SidePane {
    private static final int UNIT = 16;

    private SidePane() {
    }

    public static JScrollPane scrolling(JComponent side) {
        JScrollPane scroll = new JScrollPane(new WidthTracking(side), ScrollPaneConstants.VERTICAL_SCROLLBAR_ALWAYS,
                ScrollPaneConstants.HORIZONTAL_SCROLLBAR_NEVER);
        scroll.setBorder(null);
        return scroll;
    }

    /** The side, as wide as the viewport: the scroll bar takes its room from the pane, not from the side. */
    private static final class WidthTracking extends JPanel implements Scrollable {
        WidthTracking(JComponent side) {
            super(new BorderLayout());
            add(side, BorderLayout.CENTER);
        }

        @Override
        public Dimension getPreferredScrollableViewportSize() {
            return getPreferredSize();
        }

        @Override
        public int getScrollableUnitIncrement(Rectangle visible, int orientation, int direction) {
            return UNIT;
        }

        @Override
        public int getScrollableBlockIncrement(Rectangle visible, int orientation, int direction) {
            return Math.max(UNIT, visible.height - UNIT);
        }

        @Override
        public boolean getScrollableTracksViewportWidth() {
            return true;
        }

        @Override
        public boolean getScrollableTracksViewportHeight() {
            return false;
        }
    }
}
