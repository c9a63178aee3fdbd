package gizmoball.view;

import gizmoball.model.Board;
import gizmoball.model.BoardChange;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.BallReport;
import gizmoball.model.loop.Stage;
import gizmoball.model.loop.TickReport;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.awt.geom.RoundRectangle2D;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import physics.Vect;

/**
 * View > Physics overlay: the loop made visible. For each free ball its velocity, its next collision (where
 * its centre will be, and in how long) and whether it flies, rests in contact or sleeps; in a corner, what
 * the last tick cost stage by stage, how many collisions it resolved and how many balls were awake.
 * <p>
 * Every number is read from the model's {@link TickReport}, the read-only snapshot taken at stage 6; the
 * overlay computes nothing of the physics itself. While shown, it asks the board to look ahead for each
 * ball's next collision (which costs a detection pass per ball and tick, so it is off otherwise).
 */
public final class PhysicsOverlay implements BoardOverlay {
    /** How far ahead the report looks for a ball's next collision. */
    static final double LOOK_AHEAD_SECONDS = 2;
    /** A velocity is drawn as the way the ball goes in this time. */
    static final double VECTOR_SECONDS = 0.1;
    private static final Color VELOCITY = new Color(0x7cf29c);
    private static final Color NEXT = new Color(0xffd166);
    private static final Color FLYING = new Color(0x8fd3ff);
    private static final Color CONTACT = new Color(0xff9f43);
    private static final Color ASLEEP = new Color(0xa0a0a0);
    private static final Color PANEL = new Color(10, 12, 18, 200);
    private static final Color TEXT = new Color(0xe8ecf4);
    private static final float[] DASH = {4f, 4f};

    static final Font FONT = new Font(Font.MONOSPACED, Font.PLAIN, 11);
    /** The panel keeps this far from the board and from the view's edge. */
    private static final int GAP = 6;

    private final Board board;
    private boolean enabled;
    /** The report of the last tick of the board shown now: none after a load or Reset, until it ticks. */
    private TickReport shown = TickReport.NONE;

    private PhysicsOverlay(Board board) {
        this.board = board;
    }

    /** The overlay of {@code board}, following its ticks (registered once the overlay is whole). */
    public static PhysicsOverlay of(Board board) {
        PhysicsOverlay overlay = new PhysicsOverlay(board);
        board.addObserver((Board b, BoardChange change) ->
                overlay.shown = change == BoardChange.TICK ? b.lastTick() : TickReport.NONE);
        return overlay;
    }

    /** What the overlay shows: the last tick's report, or {@link TickReport#NONE} since a load, an edit or Reset. */
    TickReport shown() {
        return shown;
    }

    public boolean isEnabled() {
        return enabled;
    }

    public void setEnabled(boolean on) {
        enabled = on;
        board.setNextCollisionLookAhead(on ? LOOK_AHEAD_SECONDS : 0);
        board.setStageTiming(on);
    }

    /**
     * The panel's lines for {@code r}: the tick, the six stage times in the order the loop runs them (detection
     * before motion: the product description numbers them otherwise, docs/rules.md, "The tick", and the panel says
     * so), collisions, balls awake. Short lines, so that the panel fits beside the board in most windows.
     */
    static List<String> panelLines(TickReport r) {
        List<String> lines = new ArrayList<>();
        if (r == TickReport.NONE) {
            lines.add("no tick since a load,");
            lines.add("an edit or Reset");
            return lines;
        }
        lines.add(String.format(Locale.ROOT, "tick at t = %.3f s", r.time()));
        lines.add("stages, in run order:");
        long total = 0;
        for (Stage stage : Stage.values()) {
            long nanos = r.stageNanos().get(stage);
            total += nanos;
            lines.add(String.format(Locale.ROOT, "%d %-10s %7.1f us", stage.number(), stageName(stage), nanos / 1e3));
        }
        lines.add(String.format(Locale.ROOT, "  %-10s %7.1f us", "total", total / 1e3));
        lines.add(String.format(Locale.ROOT, "collisions %d", r.collisions()));
        lines.add(String.format(Locale.ROOT, "  %d at zero time", r.zeroTimeCollisions()));
        lines.add(String.format(Locale.ROOT, "  %d at once apart", r.simultaneousCollisions()));
        lines.add(String.format(Locale.ROOT, "balls awake %d", r.ballsAwake()));
        lines.add(String.format(Locale.ROOT, "balls asleep %d", r.ballsAsleep()));
        return lines;
    }

    /** The label under a ball: its state, and when its next collision is. */
    static String ballLabel(BallReport b) {
        String state = b.state().name().toLowerCase(Locale.ROOT);
        return Double.isFinite(b.nextCollisionIn())
                ? String.format(Locale.ROOT, "%s, hit in %.3f s", state, b.nextCollisionIn())
                : state;
    }

    private static String stageName(Stage stage) {
        return switch (stage) {
            case FRICTION_AND_GRAVITY -> "forces";
            case BALL_MOTION -> "motion";
            case COLLISION_DETECTION -> "detection";
            case COLLISION_RESOLUTION -> "resolution";
            case TRIGGERING -> "triggers";
            case REDRAWING -> "redraw";
        };
    }

    /** A ball's label and where it goes. */
    record Label(String text, Rectangle2D box) { }

    /** Where everything written goes: the tick panel, and the balls' labels (none over another). */
    record Layout(Rectangle2D panel, List<String> lines, List<Label> labels) { }

    @Override
    public void paint(Graphics2D screen, BoardTransform t) {
        if (!enabled) {
            return;
        }
        Graphics2D g = (Graphics2D) screen.create();
        try {
            g.setFont(FONT);
            Layout layout = layout(g.getFontMetrics(), t, shown);
            for (BallReport ball : shown.balls()) {
                paintBall(g, t, ball);
            }
            for (Label label : layout.labels()) {
                g.drawString(label.text(), (float) label.box().getX(),
                        (float) (label.box().getY() + g.getFontMetrics().getAscent()));
            }
            paintPanel(g, layout.panel(), layout.lines());
        } finally {
            g.dispose();
        }
    }

    /** The layout of {@code report}'s writing over the view {@code t} in the font {@code m} measures. */
    Layout layout(FontMetrics m, BoardTransform t, TickReport report) {
        List<String> lines = panelLines(report);
        Rectangle2D panel = panelBox(m, t, lines);
        List<Label> labels = new ArrayList<>();
        for (BallReport ball : report.balls()) {
            String text = ballLabel(ball);
            List<Rectangle2D> taken = new ArrayList<>(labels.stream().map(Label::box).toList());
            taken.add(panel);
            labelBox(m, t, t.toScreen(ball.position().x(), ball.position().y()), text, taken)
                    .ifPresent(box -> labels.add(new Label(text, box)));
        }
        return new Layout(panel, lines, labels);
    }

    private static void paintBall(Graphics2D g, BoardTransform t, BallReport ball) {
        Point2D at = t.toScreen(ball.position().x(), ball.position().y());
        double r = Board.BALL_RADIUS * t.scale();
        Vect next = ball.nextCollisionAt();
        if (next != null && Double.isFinite(ball.nextCollisionIn())) {
            Point2D hit = t.toScreen(next.x(), next.y());
            g.setColor(NEXT);
            g.setStroke(new BasicStroke(1f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, DASH, 0f));
            g.draw(new Line2D.Double(at, hit));
            g.setStroke(new BasicStroke(1.5f));
            g.draw(new Ellipse2D.Double(hit.getX() - r, hit.getY() - r, 2 * r, 2 * r));
        }
        Vect v = ball.velocity();
        Point2D tip = t.toScreen(ball.position().x() + v.x() * VECTOR_SECONDS, ball.position().y() + v.y() * VECTOR_SECONDS);
        g.setColor(VELOCITY);
        g.setStroke(new BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(new Line2D.Double(at, tip));
        paintArrowHead(g, at, tip);
        g.setColor(switch (ball.state()) {
            case FLYING -> FLYING;
            case CONTACT -> CONTACT;
            case ASLEEP -> ASLEEP;
        });
        g.setStroke(new BasicStroke(2f));
        g.draw(new Ellipse2D.Double(at.getX() - r - 3, at.getY() - r - 3, 2 * r + 6, 2 * r + 6));
    }

    /**
     * The text box of a ball's label, kept on the board: under the ball, else above it, else beside it (right, then
     * left), whichever first overlaps none of the boxes {@code taken}; none if every place does (the ball's ring
     * still says its state by its colour).
     */
    static Optional<Rectangle2D> labelBox(FontMetrics m, BoardTransform t, Point2D ball, String label,
                                         List<Rectangle2D> taken) {
        double r = Board.BALL_RADIUS * t.scale();
        double width = m.stringWidth(label);
        double height = m.getHeight();
        double[][] places = {
            {ball.getX() - width / 2, ball.getY() + r + 4},
            {ball.getX() - width / 2, ball.getY() - r - 4 - height},
            {ball.getX() + r + 6, ball.getY() - height / 2},
            {ball.getX() - r - 6 - width, ball.getY() - height / 2},
        };
        for (double[] place : places) {
            Rectangle2D box = BoardTransform.keptInside(new Rectangle2D.Double(place[0], place[1], width, height),
                    t.board());
            if (taken.stream().noneMatch(box::intersects)) {
                return Optional.of(box);
            }
        }
        return Optional.empty();
    }

    private static void paintArrowHead(Graphics2D g, Point2D from, Point2D tip) {
        double dx = tip.getX() - from.getX();
        double dy = tip.getY() - from.getY();
        double length = Math.hypot(dx, dy);
        if (length < 4) {
            return;
        }
        double ux = dx / length;
        double uy = dy / length;
        double size = Math.min(8, length / 2);
        Path2D.Double head = new Path2D.Double();
        head.moveTo(tip.getX(), tip.getY());
        head.lineTo(tip.getX() - size * (ux - uy / 2), tip.getY() - size * (uy + ux / 2));
        head.lineTo(tip.getX() - size * (ux + uy / 2), tip.getY() - size * (uy - ux / 2));
        head.closePath();
        g.fill(head);
    }

    /**
     * Where the panel goes: beside the board where the view has room for it (a window wider than the board, as
     * play mode's usually is), so that it covers nothing; otherwise in the board's corner that covers the fewest
     * gizmos and balls.
     */
    Rectangle2D panelBox(FontMetrics m, BoardTransform t, List<String> lines) {
        int width = lines.stream().mapToInt(m::stringWidth).max().orElse(0) + 12;
        int height = lines.size() * m.getHeight() + 8;
        Rectangle2D area = t.board();
        if (area.getMinX() - t.component().getMinX() >= width + GAP) {
            return new Rectangle2D.Double(area.getMinX() - GAP - width, area.getMinY(), width, height);
        }
        Rectangle2D best = null;
        int fewest = Integer.MAX_VALUE;
        for (double x : new double[] {area.getMinX() + GAP, area.getMaxX() - GAP - width}) {
            for (double y : new double[] {area.getMinY() + GAP, area.getMaxY() - GAP - height}) {
                Rectangle2D corner = new Rectangle2D.Double(x, y, width, height);
                int covered = covered(t, corner);
                if (covered < fewest) {
                    fewest = covered;
                    best = corner;
                }
            }
        }
        return best;
    }

    private int covered(BoardTransform t, Rectangle2D box) {
        int count = 0;
        for (Gizmo gizmo : board.gizmos()) {
            Point2D a = t.toScreen(gizmo.x(), gizmo.y());
            Point2D b = t.toScreen(gizmo.x() + gizmo.width(), gizmo.y() + gizmo.height());
            count += box.intersects(a.getX(), a.getY(), b.getX() - a.getX(), b.getY() - a.getY()) ? 1 : 0;
        }
        for (BallView ball : board.balls()) {
            Point2D at = t.toScreen(ball.position().x(), ball.position().y());
            count += box.contains(at) ? 1 : 0;
        }
        return count;
    }

    private static void paintPanel(Graphics2D g, Rectangle2D box, List<String> lines) {
        FontMetrics m = g.getFontMetrics();
        g.setColor(PANEL);
        g.fill(new RoundRectangle2D.Double(box.getX(), box.getY(), box.getWidth(), box.getHeight(), 8, 8));
        g.setColor(TEXT);
        for (int i = 0; i < lines.size(); i++) {
            g.drawString(lines.get(i), (float) box.getX() + 6,
                    (float) (box.getY() + 4 + m.getAscent() + i * m.getHeight()));
        }
    }
}
