package gizmoball.view.editor;

import gizmoball.preview.Prediction;
import gizmoball.view.BoardOverlay;
import gizmoball.view.BoardTransform;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.awt.geom.RoundRectangle2D;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.Supplier;
import physics.Vect;

/**
 * Draws the aim preview: the predicted path of the ball (fading as it goes further into the future), a dot at
 * each collision, and at the first trigger the names of the gizmos it drives. A path cut short by the time
 * budget says how far it reaches.
 */
public final class AimPreviewOverlay implements BoardOverlay {
    static final Color PATH = new Color(0x5ee1ff);
    static final Color DOT = new Color(0xfff3b0);
    private static final Color LABEL_BACK = new Color(10, 12, 18, 210);
    private static final int NEAR_ALPHA = 230;
    private static final int FAR_ALPHA = 50;
    private static final double DOT_PIXELS = 3.5;

    private final Supplier<Optional<Prediction>> prediction;

    public AimPreviewOverlay(Supplier<Optional<Prediction>> prediction) {
        this.prediction = prediction;
    }

    @Override
    public void paint(Graphics2D screen, BoardTransform t) {
        Optional<Prediction> p = prediction.get();
        if (p.isEmpty()) {
            return;
        }
        Graphics2D g = (Graphics2D) screen.create();
        try {
            paintPath(g, t, p.get());
        } finally {
            g.dispose();
        }
    }

    private static void paintPath(Graphics2D g, BoardTransform t, Prediction p) {
        List<Prediction.Point> path = p.path();
        g.setStroke(new BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        int n = path.size() - 1;
        for (int i = 0; i < n; i++) {
            Prediction.Point a = path.get(i);
            Prediction.Point b = path.get(i + 1);
            if (a.free() && b.free()) {
                int alpha = (int) Math.round(NEAR_ALPHA + (FAR_ALPHA - NEAR_ALPHA) * (double) i / n);
                g.setColor(new Color(PATH.getRed(), PATH.getGreen(), PATH.getBlue(), alpha));
                g.draw(new Line2D.Double(t.toScreen(a.at().x(), a.at().y()), t.toScreen(b.at().x(), b.at().y())));
            }
        }
        g.setColor(DOT);
        for (Vect c : p.collisions()) {
            Point2D at = t.toScreen(c.x(), c.y());
            g.fill(new Ellipse2D.Double(at.getX() - DOT_PIXELS, at.getY() - DOT_PIXELS, 2 * DOT_PIXELS, 2 * DOT_PIXELS));
        }
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 12));
        p.trigger().ifPresent(tr -> label(g, t, t.toScreen(tr.at().x(), tr.at().y()),
                tr.source() + " \u2192 " + String.join(", ", tr.targets())));
        if (p.shortened() && n > 0) {
            Vect end = path.get(n).at();
            label(g, t, t.toScreen(end.x(), end.y()), String.format(Locale.ROOT, "%.1f s", p.seconds()));
        }
    }

    /** Up and to the right of the point, or moved in from the view's edge so that it is read whole. */
    private static void label(Graphics2D g, BoardTransform t, Point2D at, String text) {
        Rectangle2D box = labelBox(g.getFontMetrics(), t, at, text);
        g.setColor(LABEL_BACK);
        g.fill(new RoundRectangle2D.Double(box.getX(), box.getY(), box.getWidth(), box.getHeight(), 6, 6));
        g.setColor(DOT);
        g.drawString(text, (float) box.getX() + 4, (float) (box.getY() + 1 + g.getFontMetrics().getAscent()));
    }

    /** Where the label of {@code text} at {@code at} goes: its background, within the view. */
    static Rectangle2D labelBox(FontMetrics m, BoardTransform t, Point2D at, String text) {
        Rectangle2D wanted = new Rectangle2D.Double(at.getX() + 4, at.getY() - 8 - m.getHeight(),
                m.stringWidth(text) + 8, m.getHeight() + 2);
        return BoardTransform.keptInside(wanted, t.component());
    }
}
