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
 * afresh, and a captured ball has none (it did not travel to the absorber's corner). A ball that jumps (out of a
 * portal's pair, or fired from an absorber in the tick it was taken) starts a new trail where it reappears, and the
 * trails go when the game stops: a trail shows motion, and a stopped board has none.
 */
public final class BallTrails implements BoardOverlay {
    /** A quarter of a second at 60 ticks per second. */
    static final int LENGTH = 15;
    /**
     * A ball that moved further in a tick than this many times its greater speed (before or after) times the tick
     * jumped: its path is no longer than that speed times the tick, for gravity and friction keep the fastest point
     * of a tick's path at one of its ends, and a collision leaves the ball no faster than it ends the tick.
     */
    private static final double JUMP = 1.5;
    private static final Color COLOUR = new Color(0x8fd3ff);
    private static final int MAX_ALPHA = 170;

    private final Board board;
    private final Map<String, ArrayDeque<Vect>> trails = new HashMap<>();
    private final Map<String, Double> speeds = new HashMap<>();
    private final BoardObserver recorder = this::boardChanged;
    private double lastTime;
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
        clear();
        lastTime = board.time();
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

    /** Forgets every trail (the game stopped); the next tick starts them afresh. */
    public void clear() {
        trails.clear();
        speeds.clear();
    }

    private void boardChanged(Board b, BoardChange change) {
        double dt = b.time() - lastTime;
        lastTime = b.time();
        if (change != BoardChange.TICK) {
            clear();
            return;
        }
        trails.keySet().removeIf(name -> b.ball(name).isEmpty());
        speeds.keySet().removeIf(name -> b.ball(name).isEmpty());
        for (BallView ball : b.balls()) {
            if (ball.isCaptured()) {
                trails.remove(ball.name());
                continue;
            }
            double speed = ball.velocity().length();
            Double before = speeds.put(ball.name(), speed);
            ArrayDeque<Vect> trail = trails.computeIfAbsent(ball.name(), n -> new ArrayDeque<>());
            if (!trail.isEmpty() && jumped(trail.getLast(), ball.position(), Math.max(before, speed) * dt)) {
                trail.clear();
            }
            if (trail.size() == LENGTH) {
                trail.removeFirst();
            }
            trail.addLast(ball.position());
        }
    }

    private static boolean jumped(Vect from, Vect to, double reach) {
        return from.minus(to).length() > JUMP * reach;
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
