package gizmoball.view;

import gizmoball.model.Board;
import gizmoball.model.BoardChange;
import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.Graphics;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import javax.swing.JComponent;
import javax.swing.JViewport;
import javax.swing.Scrollable;
import javax.swing.SwingConstants;
import java.awt.Rectangle;

/**
 * The board view: observes the Board and repaints the whole board on every change (a tick, an edit, a
 * load), scaled to its size with the aspect ratio kept. Swing double-buffers it, so it never flickers.
 * Overlays (build mode's selection and previews) are drawn on top.
 * <p>
 * The fixed part of the board (everything but flippers, balls and highlights) is drawn once per edit into
 * an image at the screen's device resolution and copied on each frame: antialiased drawing of hundreds of
 * gizmos would otherwise cost more than a 60 Hz frame on a slow machine.
 * <p>
 * It sits in a scroll pane ({@link BoardZoom}): fitting the view unless zoomed, then as large as the zoom makes it.
 */
public final class BoardPanel extends JComponent implements Scrollable {
    private static final int PREFERRED_PIXELS_PER_L = 30;
    /** Room around the board for the outer walls. */
    static final int MARGIN = 6;

    private final transient Board board;
    private final transient List<BoardOverlay> overlays = new ArrayList<>();
    private final transient List<BoardOverlay> underlays = new ArrayList<>();
    private final transient FpsMeter fps = new FpsMeter();
    private final transient Interpolation between = new Interpolation();
    private boolean gridVisible;
    /** Counts edits and loads (not ticks): the fixed image is redrawn when it moves on. */
    private final AtomicLong layout = new AtomicLong();
    private transient BufferedImage fixedImage;
    private transient List<Object> fixedImageKey;
    /** Pixels per L the view is zoomed to (it scrolls then), or 0: the board fits the view (see {@link BoardZoom}). */
    private int zoomedScale;

    private BoardPanel(Board board) {
        this.board = board;
        setOpaque(true);
        setDoubleBuffered(true);
        setFocusable(true);
        int side = PREFERRED_PIXELS_PER_L * Board.SIZE + 2 * MARGIN;
        setPreferredSize(new Dimension(side, side));
        setMinimumSize(new Dimension(4 * Board.SIZE, 4 * Board.SIZE));
    }

    /** A view of {@code board}, repainting on its every change (registered once the view is whole). */
    public static BoardPanel of(Board board) {
        BoardPanel panel = new BoardPanel(board);
        panel.between.reset(board);
        board.addObserver((Board b, BoardChange change) -> {
            if (change == BoardChange.TICK) {
                panel.between.ticked(b);
            } else {
                panel.layout.incrementAndGet();
                panel.between.reset(b);
            }
            panel.repaint();
        });
        return panel;
    }

    /** The mapping between board and pixels at the panel's current size. */
    public BoardTransform transform() {
        return BoardTransform.fit(getWidth(), getHeight(), MARGIN);
    }

    public void addOverlay(BoardOverlay overlay) {
        overlays.add(overlay);
        repaint();
    }

    /** Drawn over the fixed part of the board but under the flippers and balls (ball trails). */
    public void addUnderlay(BoardOverlay underlay) {
        underlays.add(underlay);
        repaint();
    }

    public void setGridVisible(boolean visible) {
        gridVisible = visible;
        repaint();
    }

    /**
     * How far real time has come from the last tick towards the next (0..1; 1 when stopped): balls and flippers
     * are drawn that far between the last two ticks, so slow motion moves at the display's rate.
     */
    public void setTickFraction(double fraction) {
        if (fraction != between.fraction()) {
            between.setFraction(fraction);
            repaint();
        }
    }

    /** Zooms to {@code pixelsPerL} (0: fit the view); the caller lays out the scroll pane around it. */
    void setZoomedScale(int pixelsPerL) {
        zoomedScale = pixelsPerL;
        revalidate();
        repaint();
    }

    /** The zoom's pixels per L, or 0 when the board fits the view. */
    int zoomedScale() {
        return zoomedScale;
    }

    /** Zoomed, the board at its scale with the walls' margin; else the size it would like when it fits. */
    @Override
    public Dimension getPreferredSize() {
        if (zoomedScale == 0) {
            return super.getPreferredSize();
        }
        int side = zoomedScale * Board.SIZE + 2 * MARGIN;
        return new Dimension(side, side);
    }

    @Override
    public Dimension getPreferredScrollableViewportSize() {
        return getPreferredSize();
    }

    /** One L a click of the scroll bar's arrows. */
    @Override
    public int getScrollableUnitIncrement(Rectangle visible, int orientation, int direction) {
        return Math.max(1, (int) transform().scale());
    }

    @Override
    public int getScrollableBlockIncrement(Rectangle visible, int orientation, int direction) {
        return Math.max(1, (orientation == SwingConstants.HORIZONTAL ? visible.width : visible.height) * 9 / 10);
    }

    /** Fitting, the view's size is the viewport's; zoomed, it is its own, or the viewport's where that is larger. */
    @Override
    public boolean getScrollableTracksViewportWidth() {
        return zoomedScale == 0 || getParent() instanceof JViewport v && v.getWidth() >= getPreferredSize().width;
    }

    @Override
    public boolean getScrollableTracksViewportHeight() {
        return zoomedScale == 0 || getParent() instanceof JViewport v && v.getHeight() >= getPreferredSize().height;
    }

    /** Frames painted in the last second. */
    public int framesPerSecond() {
        return fps.fps(System.nanoTime());
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
            g.setRenderingHint(RenderingHints.KEY_RENDERING, RenderingHints.VALUE_RENDER_QUALITY);
            BoardTransform t = transform();
            Rectangle visible = visibleArea();
            g.drawImage(fixedImage(g, t, visible), visible.x, visible.y, visible.width, visible.height, null);
            for (BoardOverlay underlay : underlays) {
                underlay.paint(g, t);
            }
            BoardPainter.paintMoving(g, board, t, between);
            for (BoardOverlay overlay : overlays) {
                overlay.paint(g, t);
            }
        } finally {
            g.dispose();
        }
        fps.frame(System.nanoTime());
    }

    /** The part of the view that shows (all of it unless zoomed in a scroll pane), never empty. */
    private Rectangle visibleArea() {
        Rectangle visible = getVisibleRect();
        return visible.isEmpty() ? new Rectangle(0, 0, Math.max(1, getWidth()), Math.max(1, getHeight())) : visible;
    }

    /**
     * Background and the fixed part of the board within {@code visible}, at the device resolution of {@code g}
     * (HiDPI stays sharp). Drawn in vector form at the view's scale, never a bitmap scaled up: zoomed in, only the
     * part that shows is drawn, so the image stays the size of the view.
     */
    private BufferedImage fixedImage(Graphics2D g, BoardTransform t, Rectangle visible) {
        AffineTransform device = g.getTransform();
        double sx = device.getScaleX();
        double sy = device.getScaleY();
        List<Object> key = List.of(getWidth(), getHeight(), visible, sx, sy, gridVisible, layout.get());
        if (!key.equals(fixedImageKey)) {
            fixedImage = new BufferedImage(Math.max(1, (int) Math.ceil(visible.width * sx)),
                    Math.max(1, (int) Math.ceil(visible.height * sy)), BufferedImage.TYPE_INT_RGB);
            Graphics2D ig = fixedImage.createGraphics();
            try {
                ig.setRenderingHints(g.getRenderingHints());
                ig.scale(sx, sy);
                ig.translate(-visible.x, -visible.y);
                ig.setColor(BoardPainter.BACKGROUND);
                ig.fillRect(visible.x, visible.y, visible.width, visible.height);
                BoardPainter.paintFixed(ig, board, t, gridVisible);
            } finally {
                ig.dispose();
            }
            fixedImageKey = key;
        }
        return fixedImage;
    }
}
