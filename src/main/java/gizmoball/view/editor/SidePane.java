package gizmoball.view.editor;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Insets;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.Rectangle;
import javax.swing.JComponent;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.ScrollPaneConstants;
import javax.swing.Scrollable;

/**
 * A build-mode side (palette or properties) that scrolls vertically when the window is too short for it, so
 * that a small window keeps every tool and field in reach without the window being resized. The scroll bar shows
 * only when the side does not fit (an empty bar beside a side that fits is only clutter).
 */
public final class SidePane {
    private static final int UNIT = 16;

    private SidePane() {
    }

    public static JScrollPane scrolling(JComponent side) {
        Scrolling scroll = new Scrolling(new WidthTracking(side));
        scroll.setBorder(null);
        scroll.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                scroll.widthMayHaveChanged();
            }
        });
        return scroll;
    }

    /**
     * As wide as the side, plus its scroll bar when the side is taller than the pane: Swing's own preferred width
     * asks whether a bar is needed of the viewport as it was, so a bar that appears takes its width from the side.
     */
    private static final class Scrolling extends JScrollPane {
        private boolean barCounted;

        Scrolling(JComponent view) {
            super(view, ScrollPaneConstants.VERTICAL_SCROLLBAR_AS_NEEDED,
                    ScrollPaneConstants.HORIZONTAL_SCROLLBAR_NEVER);
        }

        private boolean barNeeded() {
            return getHeight() > 0 && getViewport().getView().getPreferredSize().height > getHeight();
        }

        @Override
        public Dimension getPreferredSize() {
            barCounted = barNeeded();
            Insets insets = getInsets();
            Dimension view = getViewport().getView().getPreferredSize();
            int bar = barCounted ? getVerticalScrollBar().getPreferredSize().width : 0;
            return new Dimension(view.width + bar + insets.left + insets.right,
                    view.height + insets.top + insets.bottom);
        }

        /** A new height may need the bar, or no more: the layout around then asks for the width again. */
        void widthMayHaveChanged() {
            if (barNeeded() != barCounted) {
                revalidate();
            }
        }
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
