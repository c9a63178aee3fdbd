package gizmoball.view.editor;

import gizmoball.editor.Tool;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.view.BoardPainter;

import javax.swing.Icon;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Component;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Arc2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.geom.RoundRectangle2D;
import java.util.function.Consumer;

/** A palette icon drawn with Java2D in the board's colours, so the palette looks like what it places. */
public final class ToolIcon implements Icon {
    static final int SIZE = 28;
    /** The margin around a symbol that fills the icon. */
    private static final double MARGIN = 6;

    private final Tool tool;

    public ToolIcon(Tool tool) {
        this.tool = tool;
    }

    @Override
    public int getIconWidth() {
        return SIZE;
    }

    @Override
    public int getIconHeight() {
        return SIZE;
    }

    @Override
    public void paintIcon(Component c, Graphics graphics, int x, int y) {
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.translate(x, y);
            g.setColor(EditorColors.ICON_BACKGROUND);
            g.fill(new RoundRectangle2D.Double(0, 0, SIZE, SIZE, 6, 6));
            g.setStroke(new BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
            symbol().accept(g);
        } finally {
            g.dispose();
        }
    }

    /**
     * What the icon shows: a switch over every tool without a default, so a new tool does not compile without an
     * icon, and a placement tool shows its kind ({@link #kindSymbol}, likewise over every kind).
     */
    private Consumer<Graphics2D> symbol() {
        double m = MARGIN;
        double s = SIZE - 2 * m;
        return switch (tool) {
            case SQUARE, CIRCLE, TRIANGLE, LEFT_FLIPPER, RIGHT_FLIPPER, ABSORBER, SINK, ACCELERATOR, SPAWNER, GATE,
                    DROP_TARGET, SPINNER ->
                    kindSymbol(tool.kind().orElseThrow());
            case BALL -> g -> {
                fill(g, EditorColors.BALL, new Ellipse2D.Double(6, 12, 10, 10));
                arrow(g, EditorColors.ICON_INK, 14, 14, 23, 5);
            };
            case SELECT -> g -> fill(g, EditorColors.ICON_INK, pointer());
            case ROTATE -> g -> {
                g.setColor(EditorColors.ICON_INK);
                g.draw(new Arc2D.Double(m, m, s, s, 100, -300, Arc2D.OPEN));
                arrowHead(g, EditorColors.ICON_INK, 11, 9, 15, 6.5);
            };
            case DELETE -> g -> {
                g.setColor(EditorColors.REFUSED);
                g.setStroke(new BasicStroke(3.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
                g.draw(new Line2D.Double(m + 2, m + 2, SIZE - m - 2, SIZE - m - 2));
                g.draw(new Line2D.Double(SIZE - m - 2, m + 2, m + 2, SIZE - m - 2));
            };
            case CONNECT -> ToolIcon::connection;
            case DISCONNECT -> g -> {
                connection(g);
                slash(g);
            };
            case KEY_CONNECT -> ToolIcon::keyCap;
            case KEY_DISCONNECT -> g -> {
                keyCap(g);
                slash(g);
            };
        };
    }

    /** The icon of the tool that places gizmos of that kind, in the colour the board painter gives the kind. */
    private static Consumer<Graphics2D> kindSymbol(GizmoKind kind) {
        double m = MARGIN;
        double s = SIZE - 2 * m;
        return switch (kind) {
            case SQUARE -> g -> fill(g, colour(kind), new Rectangle2D.Double(m, m, s, s));
            case CIRCLE -> g -> fill(g, colour(kind), new Ellipse2D.Double(m, m, s, s));
            case TRIANGLE -> g -> fill(g, colour(kind), triangle(m, m, s));
            case LEFT_FLIPPER -> g -> flipper(g, m, m, s, true);
            case RIGHT_FLIPPER -> g -> flipper(g, m, m, s, false);
            case ABSORBER -> g -> fill(g, colour(kind), new Rectangle2D.Double(4, SIZE / 2.0, SIZE - 8, 8));
            case SINK -> g -> {
                fill(g, colour(kind), new Rectangle2D.Double(m, m, s, s));
                g.setColor(BoardPainter.SINK_HOLE);
                g.fill(new Ellipse2D.Double(m + s * 0.15, m + s * 0.15, s * 0.7, s * 0.7));
            };
            case SPAWNER -> g -> {
                fill(g, colour(kind), new Rectangle2D.Double(m, m, s, s));
                Path2D arrow = new Path2D.Double();
                arrow.moveTo(SIZE / 2.0, m + 2);
                arrow.lineTo(m + 3, SIZE / 2.0 + 3);
                arrow.lineTo(SIZE - m - 3, SIZE / 2.0 + 3);
                arrow.closePath();
                g.setColor(BoardPainter.SPAWNER_MARK);
                g.fill(arrow);
            };
            case GATE -> g -> {
                fill(g, colour(kind), new Rectangle2D.Double(m, m, s / 2 - 1, s));
                g.setColor(colour(kind));
                g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10,
                        new float[] {2.5f, 2f}, 0));
                g.draw(new Rectangle2D.Double(m + s / 2 + 1, m, s / 2 - 1, s));
            };
            case DROP_TARGET -> g -> {
                fill(g, colour(kind), new Rectangle2D.Double(m, m, s, s * 0.7));
                fill(g, colour(kind).darker(), new Rectangle2D.Double(m, m + s * 0.85, s, s * 0.15));
                g.setColor(BoardPainter.TARGET_MARK);
                g.fill(new Ellipse2D.Double(SIZE / 2.0 - 2.5, m + s * 0.35 - 2.5, 5, 5));
            };
            case SPINNER -> g -> spinner(g, m, s);
            case ACCELERATOR -> g -> {
                fill(g, colour(kind), new Ellipse2D.Double(m, m, s, s));
                g.setColor(BoardPainter.ACCELERATOR_MARK);
                g.setStroke(new BasicStroke(1.5f));
                g.draw(new Ellipse2D.Double(m + s * 0.27, m + s * 0.27, s * 0.46, s * 0.46));
            };
        };
    }

    private static void connection(Graphics2D g) {
        fill(g, colour(GizmoKind.SQUARE), new Rectangle2D.Double(3, 3, 8, 8));
        fill(g, colour(GizmoKind.CIRCLE), new Ellipse2D.Double(17, 17, 8, 8));
        arrow(g, EditorColors.CONNECTION, 10, 10, 18, 18);
    }

    /** The colour the board painter gives that kind, so the palette shows what will appear on the board. */
    private static Color colour(GizmoKind kind) {
        return BoardPainter.colourOf(kind);
    }

    private static void fill(Graphics2D g, Color color, java.awt.Shape shape) {
        g.setColor(color);
        g.fill(shape);
        g.setColor(color.darker());
        g.setStroke(new BasicStroke(1f));
        g.draw(shape);
        g.setStroke(new BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
    }

    private static Path2D triangle(double x, double y, double s) {
        Path2D p = new Path2D.Double();
        p.moveTo(x, y);
        p.lineTo(x + s, y);
        p.lineTo(x, y + s);
        p.closePath();
        return p;
    }

    /** The flipper's 2x2 box, faint, with the bar hanging at rest along its left or right edge. */
    private static void flipper(Graphics2D g, double x, double y, double size, boolean left) {
        g.setColor(EditorColors.translucent(EditorColors.ICON_INK, 70));
        g.setStroke(new BasicStroke(1f));
        g.draw(new Rectangle2D.Double(x, y, size, size));
        double barX = left ? x + 3 : x + size - 3;
        g.setColor(colour(GizmoKind.LEFT_FLIPPER));
        g.setStroke(new BasicStroke(6f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(barX, y + 3, barX, y + size - 3));
        g.setColor(EditorColors.ICON_BACKGROUND);
        g.fill(new Ellipse2D.Double(barX - 1.5, y + 1.5, 3, 3));
        g.setStroke(new BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
    }

    /** The spinner's 2x2 box, faint, with its bar across it at 30 degrees and the circle its ends sweep. */
    private static void spinner(Graphics2D g, double m, double size) {
        g.setColor(EditorColors.translucent(EditorColors.ICON_INK, 70));
        g.setStroke(new BasicStroke(1f));
        g.draw(new Rectangle2D.Double(m, m, size, size));
        g.draw(new Ellipse2D.Double(m, m, size, size));
        double c = SIZE / 2.0;
        double arm = size / 2 - 3;
        double dx = arm * Math.cos(Math.PI / 6);
        double dy = arm * Math.sin(Math.PI / 6);
        g.setColor(colour(GizmoKind.SPINNER));
        g.setStroke(new BasicStroke(6f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(c - dx, c + dy, c + dx, c - dy));
        g.setColor(EditorColors.ICON_BACKGROUND);
        g.fill(new Ellipse2D.Double(c - 1.5, c - 1.5, 3, 3));
        g.setStroke(new BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
    }

    private static Path2D pointer() {
        Path2D p = new Path2D.Double();
        p.moveTo(8, 4);
        p.lineTo(8, 22);
        p.lineTo(12.5, 17.5);
        p.lineTo(16, 24);
        p.lineTo(19, 22.5);
        p.lineTo(15.5, 16);
        p.lineTo(21, 16);
        p.closePath();
        return p;
    }

    private static void keyCap(Graphics2D g) {
        RoundRectangle2D cap = new RoundRectangle2D.Double(5, 5, 18, 18, 5, 5);
        g.setColor(Color.WHITE);
        g.fill(cap);
        g.setColor(EditorColors.ICON_BACKGROUND);
        g.draw(cap);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 12));
        g.drawString("K", 10, 19);
    }

    private static void slash(Graphics2D g) {
        g.setColor(EditorColors.REFUSED);
        g.setStroke(new BasicStroke(3f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(4, SIZE - 4, SIZE - 4, 4));
    }

    private static void arrow(Graphics2D g, Color color, double x0, double y0, double x1, double y1) {
        g.setColor(color);
        g.draw(new Line2D.Double(x0, y0, x1, y1));
        arrowHead(g, color, x0, y0, x1, y1);
    }

    private static void arrowHead(Graphics2D g, Color color, double x0, double y0, double x1, double y1) {
        g.setColor(color);
        g.fill(Arrows.head(x0, y0, x1, y1, 7));
    }
}
