package gizmoball.view;

import gizmoball.lab.HeatGrid;
import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import java.awt.AlphaComposite;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import javax.imageio.ImageIO;

/**
 * The lab's heat map: where the balls went, as a glow over a drawing of the board. The board is drawn by the board
 * painter and veiled, so the glow stands out; the time balls spent in each cell of the {@link HeatGrid} is shown on a
 * log scale of two decades (a path taken in a few games still shows beside the places every ball goes), from
 * transparent through purple, red and orange to pale yellow; the gizmos' outlines are drawn over it, and a key along
 * the bottom says what the colours mean.
 */
public final class HeatMapPicture {
    /** Pixels along the bottom for the key. */
    static final int KEY_HEIGHT = 44;
    private static final int MARGIN = 6;
    /** Cells each way that a cell's time is spread over: a ball's radius. */
    private static final int SPREAD = 1;
    /** The log scale spans this many times: a cell with a hundredth of the most-visited cell's time barely shows. */
    private static final double RANGE = 100;
    private static final Color VEIL = new Color(0, 0, 0, 130);
    private static final Color OUTLINE = new Color(255, 255, 255, 150);
    private static final Color KEY_BACKGROUND = new Color(0x15171c);
    private static final Color KEY_TEXT = new Color(0xe6e6e6);
    /** The colour scale, from the least time to the most: (red, green, blue, alpha) at evenly spaced stops. */
    private static final int[][] STOPS = {
            {40, 10, 90, 0}, {90, 20, 140, 150}, {190, 40, 90, 200}, {240, 100, 30, 225}, {255, 200, 60, 240},
            {255, 250, 200, 250}};

    private HeatMapPicture() {
    }

    /** The picture of {@code board} with {@code heat} over it, {@code side} pixels wide, with {@code caption}. */
    public static BufferedImage image(Board board, HeatGrid heat, int side, String caption) {
        BufferedImage image = new BufferedImage(side, side + KEY_HEIGHT, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            paint(g, board, heat, BoardTransform.fit(side, side, MARGIN));
            paintKey(g, side, caption);
        } finally {
            g.dispose();
        }
        return image;
    }

    /** Paints the board and the heat over it into {@code screen}, mapped by {@code t}. */
    public static void paint(Graphics2D screen, Board board, HeatGrid heat, BoardTransform t) {
        BoardPainter.paintFixed(screen, board, t, false);
        BoardPainter.paintMoving(screen, board, t, new Interpolation());
        Rectangle2D area = t.board();
        screen.setColor(VEIL);
        screen.fill(area);
        Graphics2D g = (Graphics2D) screen.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BILINEAR);
            g.setComposite(AlphaComposite.SrcOver);
            double cell = area.getWidth() / HeatGrid.SIDE;
            AffineTransform place = new AffineTransform(cell, 0, 0, cell, area.getX(), area.getY());
            g.drawImage(glow(heat), place, null);
            g.transform(t.boardToScreen());
            g.setColor(OUTLINE);
            g.setStroke(new BasicStroke((float) (1.2 / t.scale())));
            Interpolation atRest = new Interpolation();
            for (Gizmo gizmo : board.gizmos()) {
                g.draw(GizmoArt.of(gizmo.kind()).outline(gizmo, atRest));
            }
        } finally {
            g.dispose();
        }
    }

    /**
     * The heat as an image of one pixel a cell, transparent where no ball went: each cell's time spread over the
     * cells around it (a ball's radius, {@link #SPREAD} cells each way, weighted as a tent), so paths read as bands
     * and much-travelled places as broad glows rather than single cells.
     */
    private static BufferedImage glow(HeatGrid heat) {
        int side = HeatGrid.SIDE;
        double[] spread = new double[side * side];
        for (int row = 0; row < side; row++) {
            for (int column = 0; column < side; column++) {
                long time = heat.timeAt(column, row);
                if (time > 0) {
                    for (int dy = -SPREAD; dy <= SPREAD; dy++) {
                        for (int dx = -SPREAD; dx <= SPREAD; dx++) {
                            int x = column + dx;
                            int y = row + dy;
                            if (x >= 0 && x < side && y >= 0 && y < side) {
                                double weight = (SPREAD + 1 - Math.abs(dx)) * (SPREAD + 1 - Math.abs(dy));
                                spread[y * side + x] += time * weight;
                            }
                        }
                    }
                }
            }
        }
        double top = 0;
        for (double value : spread) {
            top = Math.max(top, value);
        }
        BufferedImage glow = new BufferedImage(side, side, BufferedImage.TYPE_INT_ARGB);
        double scale = Math.log1p(RANGE);
        for (int i = 0; i < spread.length; i++) {
            if (spread[i] > 0) {
                glow.setRGB(i % side, i / side, colourAt(Math.log1p(spread[i] / top * RANGE) / scale));
            }
        }
        return glow;
    }

    /** The ARGB colour of the scale at {@code level}, 0 (least) to 1 (most). */
    static int colourAt(double level) {
        double at = Math.max(0, Math.min(1, level)) * (STOPS.length - 1);
        int stop = Math.min(STOPS.length - 2, (int) at);
        double f = at - stop;
        int[] a = STOPS[stop];
        int[] b = STOPS[stop + 1];
        int[] mixed = new int[4];
        for (int i = 0; i < 4; i++) {
            mixed[i] = (int) Math.round(a[i] + (b[i] - a[i]) * f);
        }
        return mixed[3] << 24 | mixed[0] << 16 | mixed[1] << 8 | mixed[2];
    }

    private static void paintKey(Graphics2D g, int side, String caption) {
        g.setColor(KEY_BACKGROUND);
        g.fillRect(0, side, side, KEY_HEIGHT);
        int barX = 10;
        int barWidth = 160;
        int barY = side + 8;
        for (int x = 0; x < barWidth; x++) {
            int argb = colourAt((double) x / (barWidth - 1));
            g.setColor(new Color(argb, true));
            g.fillRect(barX + x, barY, 1, 12);
        }
        g.setColor(KEY_TEXT);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        g.drawString("less time", barX, barY + 26);
        g.drawString("more time", barX + barWidth - g.getFontMetrics().stringWidth("more time"), barY + 26);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        g.drawString(caption, barX + barWidth + 14, barY + 11);
        g.drawString("where the balls were (time, log scale)", barX + barWidth + 14, barY + 27);
    }

    /** The picture as PNG bytes. */
    public static byte[] png(BufferedImage image) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try {
            ImageIO.write(image, "png", bytes);
        } catch (IOException e) {
            throw new UncheckedIOException("a PNG written to memory failed", e);
        }
        return bytes.toByteArray();
    }
}
