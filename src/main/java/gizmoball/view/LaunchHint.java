package gizmoball.view;

import gizmoball.boardfile.KeyCodes;
import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.Gizmo;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.geom.Point2D;
import java.awt.geom.RoundRectangle2D;
import java.util.Optional;
import java.util.function.BooleanSupplier;

/**
 * "Press Space to launch", over the absorber that holds a ball while a key of the board fires it: the key is read from
 * the board's own bindings, so every board says its own. Shown only while {@code shown} says so (play mode, not
 * watching a replay).
 */
public final class LaunchHint implements BoardOverlay {
    private static final Color BOX = new Color(0, 0, 0, 170);
    private static final Color TEXT = new Color(0xff, 0xe0, 0x82);

    private final Board board;
    private final BooleanSupplier shown;

    public LaunchHint(Board board, BooleanSupplier shown) {
        this.board = board;
        this.shown = shown;
    }

    /** The absorber holding a ball that a key fires, and the hint for it. */
    public record Hint(Gizmo absorber, String text) {
    }

    public Optional<Hint> current() {
        if (!shown.getAsBoolean()) {
            return Optional.empty();
        }
        for (Gizmo gizmo : board.gizmos()) {
            if (!gizmo.held().isEmpty()) {
                Optional<KeyBinding> key = board.keyBindings().stream()
                        .filter(k -> k.gizmo().equals(gizmo.name())).min((a, b) -> rank(a) - rank(b));
                if (key.isPresent()) {
                    String keyName = KeyCodes.name(key.get().keyCode());
                    if (gizmo.plunger().isPresent() && key.get().edge() != KeyEdge.UP) {
                        return Optional.of(new Hint(gizmo, "Hold " + keyName + " to pull, release to launch"));
                    }
                    String verb = key.get().edge() == KeyEdge.UP ? "Press and release " : "Press ";
                    return Optional.of(new Hint(gizmo, verb + keyName + " to launch"));
                }
            }
        }
        return Optional.empty();
    }

    /** A key that fires on its way down says so first. */
    private static int rank(KeyBinding binding) {
        return binding.edge() == KeyEdge.UP ? 1 : 0;
    }

    @Override
    public void paint(Graphics2D g, BoardTransform t) {
        Optional<Hint> hint = current();
        if (hint.isEmpty()) {
            return;
        }
        Gizmo absorber = hint.get().absorber();
        String text = hint.get().text();
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, (int) Math.max(11, Math.min(28, t.scale() * 0.8))));
        FontMetrics m = g.getFontMetrics();
        Point2D centre = t.toScreen(absorber.x() + absorber.width() / 2.0, absorber.y());
        double w = m.stringWidth(text) + m.getHeight();
        double h = m.getHeight() * 1.4;
        // Above the absorber, clear of flippers at its edge, inside the board.
        double x = Math.max(t.toScreen(0, 0).getX(), Math.min(centre.getX() - w / 2, t.toScreen(Board.SIZE, 0).getX() - w));
        double y = centre.getY() - h - t.scale() * 3.5;
        g.setColor(BOX);
        g.fill(new RoundRectangle2D.Double(x, y, w, h, h / 2, h / 2));
        g.setColor(TEXT);
        g.drawString(text, (float) (x + m.getHeight() / 2.0), (float) (y + (h - m.getHeight()) / 2 + m.getAscent()));
    }
}
