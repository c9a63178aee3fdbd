package gizmoball.view.editor;

import gizmoball.boardfile.KeyCodes;
import gizmoball.editor.Editor;
import gizmoball.editor.Handle;
import gizmoball.editor.PendingStep;
import gizmoball.editor.Preview;
import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;
import gizmoball.view.BoardOverlay;
import gizmoball.view.BoardTransform;
import physics.Vect;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Shape;
import java.awt.Stroke;
import java.awt.geom.CubicCurve2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Point2D;
import java.awt.geom.QuadCurve2D;
import java.awt.geom.Rectangle2D;
import java.awt.geom.RoundRectangle2D;
import java.util.List;
import java.util.Optional;
import java.util.function.BooleanSupplier;
import java.util.stream.Collectors;

/**
 * Draws build-mode feedback over the board: the placement preview (green fits, red refused), the selection,
 * the selected gizmo's connections (outgoing cyan, incoming orange) and key bindings, and a pending Connect
 * source. Geometry is computed in board units and drawn in pixels so line widths do not scale with the window.
 */
public final class BuildOverlay implements BoardOverlay {
    private static final float LINE = 2.5f;
    /** Pixels a gizmo's selection outline stands off its footprint. */
    private static final double OUTLINE_GROW = 3;
    /** Pixels between the lines of a refused footprint's hatching. */
    private static final float HATCH_PITCH = 9f;
    /** Pixels between a selection outline (or footprint) and the label of keys beside it. */
    private static final double LABEL_GAP = 6;
    /** Pixels across a resize handle of the selected absorber. */
    private static final double HANDLE = 8;

    private final Editor controller;
    private final BooleanSupplier active;

    public BuildOverlay(Editor controller, BooleanSupplier active) {
        this.controller = controller;
        this.active = active;
    }

    @Override
    public void paint(Graphics2D graphics, BoardTransform t) {
        if (!active.getAsBoolean()) {
            return;
        }
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            controller.target().ifPresent(name -> outline(g, t, name, EditorColors.TARGET, false));
            paintSelection(g, t);
            if (controller.step() instanceof PendingStep.Banding band) {
                paintBand(g, t, band);
            }
            controller.connectSource().ifPresent(source -> {
                outline(g, t, source.name(), EditorColors.CONNECTION, true);
                controller.pointer().ifPresent(p -> rubberBand(g, t, source, p));
            });
            controller.awaitingKeyFor().flatMap(controller.board()::gizmo).ifPresent(gizmo -> {
                Point2D above = t.toScreen(gizmo.x(), gizmo.y());
                label(g, t, "press a key\u2026", above.getX(), above.getY() - 8, EditorColors.SELECTION);
            });
            controller.preview().ifPresent(p -> paintPreview(g, t, p));
        } finally {
            g.dispose();
        }
    }

    /**
     * One gizmo or ball selected: outlined, with its connections and keys. Several: each outlined (what they are
     * connected to would be a tangle of arrows; the properties panel lists the one selected last).
     */
    private void paintSelection(Graphics2D g, BoardTransform t) {
        List<String> group = controller.selection();
        if (group.size() > 1) {
            group.forEach(name -> outline(g, t, name, EditorColors.SELECTION, false));
            return;
        }
        controller.selected().ifPresent(name -> paintSelection(g, t, name));
        for (Handle h : controller.handles()) {
            Point2D at = t.toScreen(h.x(), h.y());
            Rectangle2D square = new Rectangle2D.Double(at.getX() - HANDLE / 2, at.getY() - HANDLE / 2, HANDLE,
                    HANDLE);
            g.setColor(EditorColors.SELECTION);
            g.fill(square);
            g.setColor(Color.BLACK);
            g.setStroke(new BasicStroke(1f));
            g.draw(square);
        }
    }

    /** The rubber band of Select: a dashed rectangle over a faint fill. */
    private static void paintBand(Graphics2D g, BoardTransform t, PendingStep.Banding band) {
        Rectangle2D r = screenRect(t, Math.min(band.x0(), band.x1()), Math.min(band.y0(), band.y1()),
                Math.abs(band.x1() - band.x0()), Math.abs(band.y1() - band.y0()), 0);
        g.setColor(EditorColors.translucent(EditorColors.SELECTION, 40));
        g.fill(r);
        g.setColor(EditorColors.SELECTION);
        g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[]{5f, 4f}, 0f));
        g.draw(r);
    }

    private void paintSelection(Graphics2D g, BoardTransform t, String name) {
        Board board = controller.board();
        for (Connection c : board.connections()) {
            if (c.source().equals(TriggerSource.named(name))) {
                connectionArrow(g, t, c, EditorColors.CONNECTION);
            } else if (c.target().equals(name)) {
                connectionArrow(g, t, c, EditorColors.INCOMING);
            }
        }
        outline(g, t, name, EditorColors.SELECTION, false);
        board.gizmo(name).ifPresent(gizmo -> keyLabel(g, t, gizmo, board.keyBindings()));
        board.ball(name).ifPresent(ball -> velocityArrow(g, t, ball.position().x(), ball.position().y(),
                ball.velocity().x(), ball.velocity().y(), EditorColors.SELECTION));
    }

    /** Outlines a gizmo's footprint, a ball, or the whole board for the outer walls. */
    private void outline(Graphics2D g, BoardTransform t, String name, Color color, boolean dashed) {
        Board board = controller.board();
        g.setColor(color);
        g.setStroke(dashed
                ? new BasicStroke(LINE, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[]{6f, 4f}, 0f)
                : new BasicStroke(LINE + 1));
        Optional<Gizmo> gizmo = board.gizmo(name);
        Optional<BallView> ball = board.ball(name);
        if (TriggerSource.named(name) instanceof TriggerSource.OuterWalls) {
            g.draw(screenRect(t, 0, 0, Board.SIZE, Board.SIZE, -2));
        } else if (gizmo.isPresent()) {
            Gizmo z = gizmo.get();
            g.draw(screenRect(t, z.x(), z.y(), z.width(), z.height(), OUTLINE_GROW));
        } else if (ball.isPresent()) {
            BallView b = ball.get();
            double r = b.radius() + 0.12;
            g.draw(screenEllipse(t, b.position().x(), b.position().y(), r));
        }
    }

    /**
     * A footprint that fits is a translucent green; a refused one is hatched black and white inside a black-edged
     * red outline, which reads over every gizmo colour (a translucent red vanished over a red square).
     */
    private void paintPreview(Graphics2D g, BoardTransform t, Preview preview) {
        paintPreview(g, t, preview, preview.fits());
    }

    /** A group's parts are drawn as it fits or is refused as a whole. */
    private void paintPreview(Graphics2D g, BoardTransform t, Preview preview, boolean fits) {
        Color color = fits ? EditorColors.FITS : EditorColors.REFUSED;
        Shape shape;
        if (preview instanceof Preview.Group group) {
            group.parts().forEach(part -> paintPreview(g, t, part, fits));
            return;
        } else if (preview instanceof Preview.Footprint f) {
            // A resize dragged past the opposite edge: the cells between the two edges, refused.
            shape = screenRect(t, Math.min(f.x(), f.x() + f.width()), Math.min(f.y(), f.y() + f.height()),
                    Math.abs(f.width()), Math.abs(f.height()), 0);
        } else {
            Preview.BallPlacement b = (Preview.BallPlacement) preview;
            shape = screenEllipse(t, b.x(), b.y(), Board.BALL_RADIUS);
            velocityArrow(g, t, b.x(), b.y(), b.vx(), b.vy(), color);
        }
        if (fits) {
            g.setColor(EditorColors.translucent(color, 90));
            g.fill(shape);
        } else {
            hatch(g, shape);
            g.setColor(Color.BLACK);
            g.setStroke(new BasicStroke(LINE + 2));
            g.draw(shape);
        }
        g.setColor(color);
        g.setStroke(new BasicStroke(LINE));
        g.draw(shape);
    }

    /** Diagonal black lines with white cores across the shape. */
    private static void hatch(Graphics2D g, Shape shape) {
        Graphics2D h = (Graphics2D) g.create();
        try {
            h.clip(shape);
            Rectangle2D r = shape.getBounds2D();
            Stroke dark = new BasicStroke(HATCH_PITCH / 2);
            Stroke light = new BasicStroke(HATCH_PITCH / 5);
            for (double d = -r.getHeight(); d < r.getWidth(); d += HATCH_PITCH) {
                Line2D line = new Line2D.Double(r.getX() + d, r.getMaxY(), r.getX() + d + r.getHeight(), r.getY());
                h.setColor(Color.BLACK);
                h.setStroke(dark);
                h.draw(line);
                h.setColor(Color.WHITE);
                h.setStroke(light);
                h.draw(line);
            }
        } finally {
            h.dispose();
        }
    }

    /** The velocity drawn as the drag that gives it (10 L/s per L), labelled with its value. */
    private static void velocityArrow(Graphics2D g, BoardTransform t, double x, double y, double vx, double vy,
                                      Color color) {
        if (vx == 0 && vy == 0) {
            return;
        }
        Point2D from = t.toScreen(x, y);
        Point2D to = t.toScreen(x + vx / Editor.VELOCITY_PER_DRAG, y + vy / Editor.VELOCITY_PER_DRAG);
        g.setStroke(new BasicStroke(LINE));
        arrow(g, from, to, color);
        label(g, t, "(" + Numbers.brief(vx) + ", " + Numbers.brief(vy) + ") L/s", to.getX() + 6, to.getY(), color);
    }

    /** Connect's first click is made: a dashed line from the source to the pointer, to where the target goes. */
    private void rubberBand(Graphics2D g, BoardTransform t, TriggerSource source, Vect pointer) {
        Rectangle2D from = sourceBox(source, new Rectangle2D.Double(pointer.x(), pointer.y(), 0, 0));
        if (from == null) {
            return;
        }
        Point2D a = edgeToward(from, pointer.x(), pointer.y());
        Point2D sa = t.toScreen(a.getX(), a.getY());
        Point2D sb = t.toScreen(pointer.x(), pointer.y());
        g.setStroke(new BasicStroke(LINE, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND, 10f,
                new float[]{6f, 6f}, 0f));
        arrow(g, sa, sb, EditorColors.CONNECTION);
    }

    private void connectionArrow(Graphics2D g, BoardTransform t, Connection c, Color color) {
        Board board = controller.board();
        Optional<Gizmo> target = board.gizmo(c.target());
        if (target.isEmpty()) {
            return;
        }
        Rectangle2D targetBox = box(target.get());
        Rectangle2D sourceBox = sourceBox(c.source(), targetBox);
        if (sourceBox == null) {
            return;
        }
        g.setStroke(new BasicStroke(LINE, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        if (c.source().equals(TriggerSource.gizmo(c.target()))) {
            selfLoop(g, t, targetBox, color);
            return;
        }
        Point2D a = edgeToward(sourceBox, targetBox.getCenterX(), targetBox.getCenterY());
        Point2D b = edgeToward(targetBox, sourceBox.getCenterX(), sourceBox.getCenterY());
        Point2D sa = t.toScreen(a.getX(), a.getY());
        Point2D sb = t.toScreen(b.getX(), b.getY());
        // Bend every arrow to its left, so A->B and B->A do not lie on top of each other.
        double dx = sb.getX() - sa.getX();
        double dy = sb.getY() - sa.getY();
        Point2D control = new Point2D.Double((sa.getX() + sb.getX()) / 2 + dy * 0.15,
                (sa.getY() + sb.getY()) / 2 - dx * 0.15);
        g.setColor(color);
        g.draw(new QuadCurve2D.Double(sa.getX(), sa.getY(), control.getX(), control.getY(), sb.getX(), sb.getY()));
        g.fill(Arrows.head(control.getX(), control.getY(), sb.getX(), sb.getY(), 12));
    }

    private static void selfLoop(Graphics2D g, BoardTransform t, Rectangle2D box, Color color) {
        Point2D start = t.toScreen(box.getCenterX() - 0.2, box.getMinY());
        Point2D end = t.toScreen(box.getCenterX() + 0.2, box.getMinY());
        double lift = t.scale() * 0.9;
        g.setColor(color);
        g.draw(new CubicCurve2D.Double(start.getX(), start.getY(), start.getX() - lift / 2,
                start.getY() - lift, end.getX() + lift / 2, end.getY() - lift, end.getX(), end.getY()));
        g.fill(Arrows.head(end.getX() + lift / 4, end.getY() - lift / 2, end.getX(), end.getY(), 10));
    }

    private static void keyLabel(Graphics2D g, BoardTransform t, Gizmo gizmo, List<KeyBinding> bindings) {
        String keys = bindings.stream().filter(k -> k.gizmo().equals(gizmo.name()))
                .map(k -> KeyCodes.name(k.keyCode()) + " " + KeyCodes.edge(k.edge()))
                .collect(Collectors.joining(", "));
        if (keys.isEmpty()) {
            return;
        }
        // Below the gizmo, clear of its selection outline; above it for the bottom row, where below is the wall.
        boolean bottomRow = gizmo.y() + gizmo.height() >= Board.SIZE;
        Point2D corner = t.toScreen(gizmo.x(), bottomRow ? gizmo.y() : gizmo.y() + gizmo.height());
        labelBeside(g, t, "keys: " + keys, corner.getX(), corner.getY(), bottomRow, EditorColors.KEY_LABEL);
    }

    /** A label whose box starts {@link #LABEL_GAP} beyond a selection outline, below or above {@code edgeY}. */
    private static void labelBeside(Graphics2D g, BoardTransform t, String text, double x, double edgeY, boolean above,
                                    Color color) {
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 12));
        FontMetrics fm = g.getFontMetrics();
        double clear = OUTLINE_GROW + (LINE + 1) / 2 + LABEL_GAP;
        // label() draws its box from (baseline - ascent - 2) to (baseline - ascent + height).
        double baseline = above ? edgeY - clear - fm.getHeight() + fm.getAscent()
                : edgeY + clear + fm.getAscent() + 2;
        label(g, t, text, x, baseline, color);
    }

    /**
     * Text on a dark rounded box so it stays readable over any gizmo colour, starting at {@code x} or, where it would
     * run past the board's right edge (a gizmo in the last columns), moved left to end there.
     */
    private static void label(Graphics2D g, BoardTransform t, String text, double x, double y, Color color) {
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 12));
        FontMetrics fm = g.getFontMetrics();
        double w = fm.stringWidth(text) + 8;
        double h = fm.getHeight();
        double start = Math.max(t.toScreen(0, 0).getX() + 4, Math.min(x, t.toScreen(Board.SIZE, 0).getX() - w + 4));
        g.setColor(new Color(0, 0, 0, 170));
        g.fill(new RoundRectangle2D.Double(start - 4, y - fm.getAscent() - 2, w, h + 2, 6, 6));
        g.setColor(color);
        g.drawString(text, (float) start, (float) y);
    }

    private static void arrow(Graphics2D g, Point2D from, Point2D to, Color color) {
        g.setColor(color);
        g.draw(new Line2D.Double(from, to));
        g.fill(Arrows.head(from.getX(), from.getY(), to.getX(), to.getY(), 12));
    }

    private static Rectangle2D box(Gizmo g) {
        return new Rectangle2D.Double(g.x(), g.y(), g.width(), g.height());
    }

    /** Where an arrow from the source toward {@code toward} starts: the gizmo's box, or a point on the walls. */
    private Rectangle2D sourceBox(TriggerSource source, Rectangle2D toward) {
        return source instanceof TriggerSource.OfGizmo gizmo
                ? controller.board().gizmo(gizmo.gizmo()).map(BuildOverlay::box).orElse(null)
                : wallPoint(toward);
    }

    /** The point of the outer walls nearest to the target, as an empty box for the arrow to start from. */
    private static Rectangle2D wallPoint(Rectangle2D target) {
        double cx = target.getCenterX();
        double cy = target.getCenterY();
        double[] distances = {cx, Board.SIZE - cx, cy, Board.SIZE - cy};
        int nearest = 0;
        for (int i = 1; i < distances.length; i++) {
            if (distances[i] < distances[nearest]) {
                nearest = i;
            }
        }
        return switch (nearest) {
            case 0 -> new Rectangle2D.Double(0, cy, 0, 0);
            case 1 -> new Rectangle2D.Double(Board.SIZE, cy, 0, 0);
            case 2 -> new Rectangle2D.Double(cx, 0, 0, 0);
            default -> new Rectangle2D.Double(cx, Board.SIZE, 0, 0);
        };
    }

    /** Where the ray from the box's centre toward (x, y) leaves the box. */
    private static Point2D edgeToward(Rectangle2D box, double x, double y) {
        double cx = box.getCenterX();
        double cy = box.getCenterY();
        double dx = x - cx;
        double dy = y - cy;
        double sx = dx == 0 ? Double.POSITIVE_INFINITY : box.getWidth() / 2 / Math.abs(dx);
        double sy = dy == 0 ? Double.POSITIVE_INFINITY : box.getHeight() / 2 / Math.abs(dy);
        double s = Math.min(Math.min(sx, sy), 1);
        return new Point2D.Double(cx + dx * s, cy + dy * s);
    }

    private static Rectangle2D screenRect(BoardTransform t, double x, double y, double w, double h, double grow) {
        Point2D a = t.toScreen(x, y);
        Point2D b = t.toScreen(x + w, y + h);
        return new Rectangle2D.Double(a.getX() - grow, a.getY() - grow,
                b.getX() - a.getX() + 2 * grow, b.getY() - a.getY() + 2 * grow);
    }

    private static Ellipse2D screenEllipse(BoardTransform t, double cx, double cy, double r) {
        Point2D a = t.toScreen(cx - r, cy - r);
        Point2D b = t.toScreen(cx + r, cy + r);
        return new Ellipse2D.Double(a.getX(), a.getY(), b.getX() - a.getX(), b.getY() - a.getY());
    }
}
