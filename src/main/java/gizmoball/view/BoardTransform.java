package gizmoball.view;

import gizmoball.model.Board;
import java.awt.geom.AffineTransform;
import java.awt.geom.Point2D;
import physics.Vect;

/**
 * Maps board coordinates (L, y downward) to component pixels and back. The 20x20 board keeps its aspect
 * ratio and is centred; one L is a whole number of pixels (SPEC: grid lines then fall on pixel
 * boundaries and stay crisp). HiDPI screens are handled by Java2D's own device scaling on top of this.
 */
public final class BoardTransform {
    private final double scale;
    private final double offsetX;
    private final double offsetY;

    private BoardTransform(double scale, double offsetX, double offsetY) {
        this.scale = scale;
        this.offsetX = offsetX;
        this.offsetY = offsetY;
    }

    /**
     * The largest whole-pixel scale at which the board, with {@code margin} pixels free around it for the
     * walls, fits a component of that size (at least 1 px per L).
     */
    public static BoardTransform fit(int width, int height, int margin) {
        int scale = Math.max(1, (Math.min(width, height) - 2 * margin) / Board.SIZE);
        int side = scale * Board.SIZE;
        return new BoardTransform(scale, Math.floor((width - side) / 2.0), Math.floor((height - side) / 2.0));
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

    public AffineTransform boardToScreen() {
        return new AffineTransform(scale, 0, 0, scale, offsetX, offsetY);
    }
}
