package gizmoball.view;

import gizmoball.model.Board;
import java.awt.geom.AffineTransform;
import java.awt.geom.Rectangle2D;
import java.awt.geom.Point2D;
import physics.Vect;

/**
 * Maps board coordinates (L, y downward) to component pixels and back. The 20x20 board keeps its aspect
 * ratio and is centred; one L is a whole number of pixels (docs/rules.md, "Units and the board": grid lines then
 * fall on pixel boundaries and stay crisp). HiDPI screens are handled by Java2D's own device scaling on top of this.
 */
public final class BoardTransform {
    private final double scale;
    private final double offsetX;
    private final double offsetY;
    private final int width;
    private final int height;

    private BoardTransform(double scale, double offsetX, double offsetY, int width, int height) {
        this.scale = scale;
        this.offsetX = offsetX;
        this.offsetY = offsetY;
        this.width = width;
        this.height = height;
    }

    /**
     * The largest whole-pixel scale at which the board, with {@code margin} pixels free around it for the
     * walls, fits a component of that size (at least 1 px per L).
     */
    public static BoardTransform fit(int width, int height, int margin) {
        int scale = Math.max(1, (Math.min(width, height) - 2 * margin) / Board.SIZE);
        int side = scale * Board.SIZE;
        return new BoardTransform(scale, Math.floor((width - side) / 2.0), Math.floor((height - side) / 2.0), width,
                height);
    }

    /** Pixels per L. */
    public double scale() {
        return scale;
    }

    public Point2D toScreen(double x, double y) {
        return new Point2D.Double(offsetX + x * scale, offsetY + y * scale);
    }

    public Vect toBoard(double px, double py) {
        return new Vect((px - offsetX) / scale, (py - offsetY) / scale);
    }

    /** The whole component, in pixels: where overlays may draw. */
    public Rectangle2D component() {
        return new Rectangle2D.Double(0, 0, width, height);
    }

    /** The board's 20 x 20 L, in pixels. */
    public Rectangle2D board() {
        return new Rectangle2D.Double(offsetX, offsetY, Board.SIZE * scale, Board.SIZE * scale);
    }

    /**
     * {@code box} (a label's, in pixels) moved as little as needed to lie inside {@code area}: a label near an edge
     * is drawn whole, on the board's side of the edge.
     */
    public static Rectangle2D keptInside(Rectangle2D box, Rectangle2D area) {
        double x = Math.max(area.getMinX(), Math.min(box.getX(), area.getMaxX() - box.getWidth()));
        double y = Math.max(area.getMinY(), Math.min(box.getY(), area.getMaxY() - box.getHeight()));
        return new Rectangle2D.Double(x, y, box.getWidth(), box.getHeight());
    }

    public AffineTransform boardToScreen() {
        return new AffineTransform(scale, 0, 0, scale, offsetX, offsetY);
    }
}
