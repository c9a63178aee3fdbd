package gizmoball.view;

import gizmoball.model.Board;
import gizmoball.model.BoardChange;
import gizmoball.model.BoardObserver;
import gizmoball.model.loop.BallView;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Line2D;
import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import physics.Vect;

/**
 * View > Ball trails: a short fading tail behind each ball, its positions at the last {@link #LENGTH} ticks.
 * Painted under the moving parts, so the ball itself stays on top. An edit or a new board starts the trails
 * afresh, and a captured ball has none (it did not travel to the absorber's corner).
 */
public final class BallTrails implements BoardOverlay {
    /** A quarter of a second at 60 ticks per second. */
    static final int LENGTH = 15;
    private static final Color COLOUR = new Color(0x8fd3ff);
    private static final int MAX_ALPHA = 170;

    private final Board board;
    private final Map<String, ArrayDeque<Vect>> trails = new HashMap<>();
    private final BoardObserver recorder = this::boardChanged;
    private boolean enabled;

    public BallTrails(Board board) {
        this.board = board;
    }

    public boolean isEnabled() {
        return enabled;
    }

    /** Only an enabled trail observes the board, so a disabled one costs nothing per tick. */
    public void setEnabled(boolean on) {
        if (on == enabled) {
            return;
        }
        enabled = on;
        trails.clear();
        if (on) {
            board.addObserver(recorder);
        } else {
            board.removeObserver(recorder);
        }
    }

    /** The positions remembered for {@code ball}, oldest first. */
    List<Vect> trail(String ball) {
        ArrayDeque<Vect> trail = trails.get(ball);
        return trail == null ? List.of() : List.copyOf(trail);
    }

    private void boardChanged(Board b, BoardChange change) {
        if (change != BoardChange.TICK) {
            trails.clear();
            return;
        }
        trails.keySet().removeIf(name -> b.ball(name).isEmpty());
        for (BallView ball : b.balls()) {
            if (ball.isCaptured()) {
                trails.remove(ball.name());
                continue;
            }
            ArrayDeque<Vect> trail = trails.computeIfAbsent(ball.name(), n -> new ArrayDeque<>());
            if (trail.size() == LENGTH) {
                trail.removeFirst();
            }
            trail.addLast(ball.position());
        }
    }

    @Override
    public void paint(Graphics2D screen, BoardTransform t) {
        if (!enabled) {
            return;
        }
        Graphics2D g = (Graphics2D) screen.create();
        try {
            g.transform(t.boardToScreen());
            for (ArrayDeque<Vect> trail : trails.values()) {
                paintTrail(g, List.copyOf(trail));
            }
        } finally {
            g.dispose();
        }
    }

    /** Segment i of n is (i+1)/n as opaque and as wide as the ball's diameter times that. */
    private static void paintTrail(Graphics2D g, List<Vect> points) {
        int n = points.size() - 1;
        for (int i = 0; i < n; i++) {
            double weight = (i + 1.0) / n;
            g.setColor(new Color(COLOUR.getRed(), COLOUR.getGreen(), COLOUR.getBlue(), (int) (MAX_ALPHA * weight)));
            g.setStroke(new BasicStroke((float) (2 * Board.BALL_RADIUS * weight), BasicStroke.CAP_ROUND,
                    BasicStroke.JOIN_ROUND));
            Vect a = points.get(i);
            Vect b = points.get(i + 1);
            g.draw(new Line2D.Double(a.x(), a.y(), b.x(), b.y()));
        }
    }
}
