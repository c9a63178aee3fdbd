package gizmoball.view;

import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.font.GlyphVector;
import java.awt.Graphics2D;
import java.awt.Shape;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.stream.Collectors;
import physics.Circle;
import physics.Vect;

/**
 * Draws a board from the model's state alone. Everything is drawn in board coordinates (L) through the
 * transform, so shapes, flipper angles and ball positions are exactly those of the model at any scale.
 */
public final class BoardPainter {
    static final Color BACKGROUND = new Color(0x14161c);
    static final Color FLOOR = new Color(0x1f2432);
    static final Color WALLS = new Color(0x9aa3b5);
    static final Color GRID = new Color(0x323a4d);
    static final Color BALL = new Color(0xf2f2f2);
    /** The hole in a sink's cell, where the balls it takes go. */
    public static final Color SINK_HOLE = new Color(0x07080b);
    /** The arrow on a spawner that points to its mouth. */
    public static final Color SPAWNER_MARK = new Color(0xe8fffb);
    /** A portal's mouth while it has a pair; without one the mouth is drawn as its frame, a wall. */
    public static final Color PORTAL_MOUTH = new Color(0x9ff3ff);
    /** The bull's-eye on a drop target that is up. */
    public static final Color TARGET_MARK = new Color(0xfff0f5);
    /** The ring on an accelerator that tells it from a circle bumper. */
    public static final Color ACCELERATOR_MARK = new Color(0xfff1d6);
    /** Size in L of the number of balls an absorber holds, written on the ball in its corner. */
    private static final float HELD_COUNT_FONT = 0.36f;
    private static final Color HELD_COUNT = new Color(0x202020);
    /** A plunger's rod and knob. */
    private static final Color PLUNGER = new Color(0xd8dce6);
    /** L: the knob's height, and how far above a held ball it stands at rest (a full pull brings it down to it). */
    private static final double PLUNGER_KNOB = 0.12;
    private static final double PLUNGER_TRAVEL = 0.3;
    /** Thickness of the outer walls, drawn just outside the board. */
    static final int WALL_PIXELS = 3;
    /** How long (simulated seconds) a triggered gizmo stays lit, fading out. */
    static final double FLASH_SECONDS = 0.15;
    /** At the trigger a gizmo's fill is this far from its colour towards white. */
    private static final double FLASH_WHITENESS = 0.85;
    /** Width in L of the glow drawn around a flashing gizmo's outline (half of it outside the gizmo). */
    private static final float HALO_WIDTH = 0.35f;
    private static final int HALO_ALPHA = 210;
    /** The fixed part draws every gizmo where it is: nothing recorded, nothing to draw between. */
    private static final Interpolation AT_REST = new Interpolation();

    private BoardPainter() {
    }

    /** The fill colour of a gizmo kind at rest ({@link GizmoArt#colourOf}). */
    public static Color colourOf(GizmoKind kind) {
        return GizmoArt.colourOf(kind);
    }

    /** The fill colour of a gizmo at rest: its own colour if it has one, otherwise its kind's. */
    public static Color colourOf(Gizmo gizmo) {
        return gizmo.colour().map(rgb -> new Color(rgb.packed())).orElseGet(() -> colourOf(gizmo.kind()));
    }

    /**
     * Paints into {@code screen}, whose coordinates are the component's pixels, the part of the board that
     * only an edit changes: floor, grid, walls and every gizmo whose picture play does not change
     * ({@link GizmoArt#changesInPlay}), in their resting colours. A view may cache it between edits.
     */
    public static void paintFixed(Graphics2D screen, Board board, BoardTransform t, boolean grid) {
        Graphics2D g = inBoardUnits(screen, t);
        try {
            float pixel = (float) (1 / t.scale());
            g.setColor(FLOOR);
            g.fill(new Rectangle2D.Double(0, 0, Board.SIZE, Board.SIZE));
            if (grid) {
                paintGrid(g, pixel);
            }
            for (Gizmo gizmo : board.gizmos()) {
                GizmoArt art = GizmoArt.of(gizmo.kind());
                if (!art.changesInPlay()) {
                    art.paint(g, gizmo, AT_REST, colourOf(gizmo), pixel);
                }
            }
            g.setColor(WALLS);
            float wall = WALL_PIXELS * pixel;
            g.setStroke(new BasicStroke(wall));
            g.draw(new Rectangle2D.Double(-wall / 2, -wall / 2, Board.SIZE + wall, Board.SIZE + wall));
        } finally {
            g.dispose();
        }
    }

    /**
     * The part that changes while playing, drawn over {@link #paintFixed}: highlights, the gizmos play changes
     * (flippers) and balls, the balls and flippers where {@code between} says between two ticks.
     */
    static void paintMoving(Graphics2D screen, Board board, BoardTransform t, Interpolation between) {
        Graphics2D g = inBoardUnits(screen, t);
        try {
            float pixel = (float) (1 / t.scale());
            for (Gizmo gizmo : board.gizmos()) {
                GizmoArt art = GizmoArt.of(gizmo.kind());
                double glow = glow(board, gizmo);
                if (glow > 0) {
                    paintHalo(g, art.outline(gizmo, between), glow);
                }
                if (art.changesInPlay() || glow > 0) {
                    art.paint(g, gizmo, between, lit(colourOf(gizmo), glow), pixel);
                }
            }
            paintPlungers(g, board, pixel);
            for (BallView ball : board.balls()) {
                paintShape(g, GizmoArt.circle(new Circle(between.ball(ball), ball.radius())), BALL, pixel);
            }
            paintHeldCounts(g, board);
        } finally {
            g.dispose();
        }
    }

    /**
     * A plunger's spring in the column where its ball is held: a rod under a knob, and, while it is pulled, a glow that
     * rises from the bottom and turns from yellow to red as the pull nears full.
     */
    private static void paintPlungers(Graphics2D g, Board board, float pixel) {
        for (Gizmo gizmo : board.gizmos()) {
            if (gizmo.plunger().isPresent()) {
                double left = gizmo.x() + gizmo.width() - 1;
                double bottom = gizmo.y() + gizmo.height();
                double pull = gizmo.pull();
                if (pull > 0) {
                    double h = pull * gizmo.height();
                    g.setColor(new Color(255, (int) Math.round(220 * (1 - pull)), 40, 200));
                    g.fill(new Rectangle2D.Double(left + 0.1, bottom - h, 0.8, h));
                }
                double knob = bottom - 2 * Board.BALL_RADIUS - PLUNGER_KNOB - (1 - pull) * PLUNGER_TRAVEL;
                g.setColor(PLUNGER);
                g.fill(new Rectangle2D.Double(left + 0.45, knob, 0.1, bottom - knob));
                paintShape(g, new Rectangle2D.Double(left + 0.2, knob, 0.6, PLUNGER_KNOB), PLUNGER, pixel);
            }
        }
    }

    /** Balls held by an absorber all sit in its corner, one on another: the top one shows how many there are. */
    private static void paintHeldCounts(Graphics2D g, Board board) {
        Map<Vect, Long> held = board.balls().stream().filter(BallView::isCaptured)
                .collect(Collectors.groupingBy(BallView::position, LinkedHashMap::new, Collectors.counting()));
        Font font = new Font(Font.SANS_SERIF, Font.BOLD, 1).deriveFont(HELD_COUNT_FONT);
        g.setColor(HELD_COUNT);
        held.forEach((at, count) -> {
            if (count > 1) {
                // Centred on the digits' ink, not on font metrics: at a fraction of an L the metrics of the scaled
                // font are too coarse to centre by, and the digits sat below the ball, half on the absorber.
                GlyphVector digits = font.createGlyphVector(g.getFontRenderContext(), Long.toString(count));
                Rectangle2D ink = digits.getVisualBounds();
                g.fill(digits.getOutline((float) (at.x() - ink.getCenterX()), (float) (at.y() - ink.getCenterY())));
            }
        });
    }

    private static Graphics2D inBoardUnits(Graphics2D screen, BoardTransform t) {
        Graphics2D g = (Graphics2D) screen.create();
        g.transform(t.boardToScreen());
        return g;
    }

    private static void paintGrid(Graphics2D g, float pixel) {
        g.setColor(GRID);
        g.setStroke(new BasicStroke(pixel));
        for (int i = 1; i < Board.SIZE; i++) {
            g.draw(new Line2D.Double(i, 0, i, Board.SIZE));
            g.draw(new Line2D.Double(0, i, Board.SIZE, i));
        }
    }

    /** Filled, with a one-pixel darker edge so that neighbouring gizmos of one kind stay distinguishable. */
    static void paintShape(Graphics2D g, Shape shape, Color fill, float pixel) {
        g.setColor(fill);
        g.fill(shape);
        g.setColor(fill.darker());
        g.setStroke(new BasicStroke(pixel));
        g.draw(shape);
    }

    /**
     * How brightly {@code gizmo} flashes now. Nothing lights once the game is over: the board's clock stops with
     * the game, and a flash that started in the last tick would otherwise stay lit until a new game.
     */
    static double glow(Board board, Gizmo gizmo) {
        return board.game().isOver() ? 0 : flash(board.time() - gizmo.lastTriggeredAt());
    }

    /** How brightly a gizmo triggered that long ago flashes: 1 at the trigger, fading linearly to 0 at FLASH_SECONDS. */
    static double flash(double secondsSinceTrigger) {
        if (!(secondsSinceTrigger >= 0 && secondsSinceTrigger < FLASH_SECONDS)) {
            return 0;
        }
        return 1 - secondsSinceTrigger / FLASH_SECONDS;
    }

    /** The colour mixed towards white as far as the flash is bright. */
    static Color lit(Color colour, double glow) {
        double w = FLASH_WHITENESS * glow;
        return new Color(mix(colour.getRed(), w), mix(colour.getGreen(), w), mix(colour.getBlue(), w));
    }

    /** A white glow around the outline, so that a flash shows even on a small gizmo and on a light colour. */
    private static void paintHalo(Graphics2D g, Shape shape, double glow) {
        g.setColor(new Color(255, 255, 255, (int) Math.round(HALO_ALPHA * glow)));
        g.setStroke(new BasicStroke(HALO_WIDTH, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(shape);
    }

    private static int mix(int channel, double towardsWhite) {
        return (int) Math.round(channel + (255 - channel) * towardsWhite);
    }
}
