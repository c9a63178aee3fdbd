package gizmoball.view;

import java.awt.Point;
import java.awt.Rectangle;
import java.awt.geom.Point2D;
import javax.swing.BorderFactory;
import javax.swing.InputMap;
import javax.swing.JComponent;
import javax.swing.JScrollPane;
import javax.swing.JViewport;
import javax.swing.SwingUtilities;
import physics.Vect;

/**
 * Zooming the board view: Ctrl+wheel over the board zooms in or out about the pointer, the View menu's items about
 * the middle of what shows, and "to fit" back to the whole board. The view sits in a scroll pane; zoomed, it is
 * larger than the pane and scrolls (the wheel without Ctrl scrolls it). Each zoom is a whole number of pixels per L,
 * and the board is drawn at that scale (never a bitmap scaled up), so it stays crisp; mouse events keep their
 * meaning because the view's own transform maps its pixels to the board at every zoom.
 */
public final class BoardZoom {
    /** Each step (a wheel notch, a menu click) zooms by this factor, at least one pixel per L. */
    static final double STEP = 1.25;
    /** Beyond this a cell is larger than most screens' part for the board: nothing more to see. */
    static final int MAX_PIXELS_PER_L = 160;

    private final BoardPanel panel;
    private final JScrollPane scroller;

    private BoardZoom(BoardPanel panel) {
        this.panel = panel;
        this.scroller = new JScrollPane(panel);
        scroller.setBorder(BorderFactory.createEmptyBorder());
        scroller.setName("board.scroller");
        // The board's keys are the board's (arrow keys are flippers and nudges): the pane must not scroll on them.
        scroller.setInputMap(JComponent.WHEN_ANCESTOR_OF_FOCUSED_COMPONENT, new InputMap());
    }

    /** The zoom of {@code panel}, in a scroll pane of its own ({@link #component}). */
    static BoardZoom of(BoardPanel panel) {
        BoardZoom zoom = new BoardZoom(panel);
        // A wheel listener on the view takes every wheel event from the pane: those without Ctrl go on to it.
        panel.addMouseWheelListener(e -> {
            if (e.isControlDown()) {
                zoom.zoom(-e.getWheelRotation(), e.getPoint());
            } else {
                zoom.scroller.dispatchEvent(SwingUtilities.convertMouseEvent(panel, e, zoom.scroller));
            }
        });
        return zoom;
    }

    /** The scroll pane holding the board view, for the window's layout. */
    public JScrollPane component() {
        return scroller;
    }

    /** Zooms in one step (positive) or out (negative) about the middle of what shows. */
    public void zoom(int steps) {
        Rectangle visible = panel.getVisibleRect();
        zoom(steps, new Point((int) visible.getCenterX(), (int) visible.getCenterY()));
    }

    /** Back to the whole board fitting the view. */
    public void fit() {
        panel.setZoomedScale(0);
        scroller.validate();
    }

    /** Whether the board is zoomed in (larger than the view, scrolling). */
    public boolean zoomed() {
        return panel.zoomedScale() > 0;
    }

    /**
     * {@code steps} steps in (positive) or out about {@code anchor} (view pixels): the board point under it stays
     * under it. Out to the size that fits the view is "fit".
     */
    void zoom(int steps, Point anchor) {
        if (steps == 0) {
            return;
        }
        JViewport viewport = scroller.getViewport();
        double now = panel.transform().scale();
        int fitting = (int) BoardTransform.fit(viewport.getWidth(), viewport.getHeight(), BoardPanel.MARGIN).scale();
        int wanted = (int) Math.round(now * Math.pow(STEP, steps));
        wanted = steps > 0 ? Math.max(wanted, (int) now + 1) : Math.min(wanted, (int) now - 1);
        if (wanted <= fitting) {
            fit();
            return;
        }
        Vect under = panel.transform().toBoard(anchor.x, anchor.y);
        Point view = viewport.getViewPosition();
        int inViewportX = anchor.x - view.x;
        int inViewportY = anchor.y - view.y;
        panel.setZoomedScale(Math.min(wanted, MAX_PIXELS_PER_L));
        scroller.validate();
        Point2D after = panel.transform().toScreen(under.x(), under.y());
        int maxX = Math.max(0, panel.getWidth() - viewport.getWidth());
        int maxY = Math.max(0, panel.getHeight() - viewport.getHeight());
        viewport.setViewPosition(new Point(clamp((int) Math.round(after.getX()) - inViewportX, maxX),
                clamp((int) Math.round(after.getY()) - inViewportY, maxY)));
    }

    private static int clamp(int v, int max) {
        return Math.max(0, Math.min(v, max));
    }
}
