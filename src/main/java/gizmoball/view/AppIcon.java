package gizmoball.view;

import gizmoball.model.Board;
import gizmoball.model.gizmo.GizmoKind;
import java.awt.Graphics2D;
import java.awt.Image;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;

/**
 * The application icon, drawn by the game's own painter: a corner of a board with a bumper, a triangle, a
 * flipper and a ball above it. The window uses it at run time; the build renders it to a PNG for the installers
 * ({@code main}: {@code AppIcon FILE [SIZE]}).
 */
public final class AppIcon {
    /** The cells of the board the icon shows: a square of {@code CELLS} cells from (X0, Y0). */
    private static final int X0 = 8;
    private static final int Y0 = 8;
    private static final int CELLS = 4;
    private static final List<Integer> WINDOW_SIZES = List.of(16, 24, 32, 48, 64, 128, 256);

    private AppIcon() {
    }

    private static Board scene() {
        Board board = new Board();
        board.addGizmo(GizmoKind.CIRCLE, "C", 8, 8);
        board.addGizmo(GizmoKind.TRIANGLE, "T", 11, 8);
        board.rotate("T");
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 9, 10);
        board.rotate("F");
        board.addBall("B", 10.4, 9.3, 0, 0);
        return board;
    }

    /** The icon, {@code size} pixels square. */
    public static BufferedImage image(int size) {
        // The painter draws whole boards at a whole number of pixels per L: draw the board large enough that
        // the icon's cells cover at least `size` pixels, then scale that corner down smoothly.
        int scale = Math.max(4, (int) Math.ceil((double) size / CELLS));
        int side = scale * Board.SIZE;
        BufferedImage full = new BufferedImage(side, side, BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = full.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        BoardTransform t = BoardTransform.fit(side, side, 0);
        Board board = scene();
        BoardPainter.paintFixed(g, board, t, false);
        BoardPainter.paintMoving(g, board, t, new Interpolation());
        g.dispose();
        BufferedImage corner = full.getSubimage(X0 * scale, Y0 * scale, CELLS * scale, CELLS * scale);
        BufferedImage icon = new BufferedImage(size, size, BufferedImage.TYPE_INT_ARGB);
        Graphics2D ig = icon.createGraphics();
        ig.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BICUBIC);
        ig.setRenderingHint(RenderingHints.KEY_RENDERING, RenderingHints.VALUE_RENDER_QUALITY);
        ig.drawImage(corner.getScaledInstance(size, size, Image.SCALE_SMOOTH), 0, 0, null);
        ig.dispose();
        return icon;
    }

    /** The sizes a window manager may want, from 16 to 256 pixels. */
    public static List<Image> windowImages() {
        return WINDOW_SIZES.stream().<Image>map(AppIcon::image).toList();
    }

    /** Writes the icon as a PNG: {@code AppIcon FILE [SIZE]} (default 256). */
    public static void main(String[] args) throws IOException {
        Path file = Path.of(args[0]);
        int size = args.length > 1 ? Integer.parseInt(args[1]) : 256;
        if (file.toAbsolutePath().getParent() != null) {
            Files.createDirectories(file.toAbsolutePath().getParent());
        }
        if (!ImageIO.write(image(size), "png", file.toFile())) {
            throw new IOException("no PNG writer in this JDK");
        }
    }
}
