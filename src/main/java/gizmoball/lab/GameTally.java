package gizmoball.lab;

import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.TriggerSource;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import physics.Vect;

/**
 * Watches one game tick by tick from outside, through the board's public API: the events of each tick (hits,
 * captures, sinks) and where each ball is, for a {@link GameResult} and the {@link HeatGrid}.
 */
final class GameTally {
    /** Seconds a ball must lie still outside an absorber to count as jammed. */
    static final double JAM_SECONDS = 3;
    /** L: a ball whose centre stays this close to where it was is lying still. */
    static final double STILL_DISTANCE = 0.05;

    /** What is known of one ball. */
    private static final class BallWatch {
        /** The tick it left its absorber, or -1 while it is not in play. */
        long inPlaySince = -1;
        /** Its centre after the last tick it was free in, NaN if it was not. */
        double lastX = Double.NaN;
        double lastY = Double.NaN;
        double stillX = Double.NaN;
        double stillY = Double.NaN;
        long stillSince;
        boolean jamCounted;
    }

    private final Board board;
    private final double dt;
    private final long jamTicks;
    /** L: the farthest a ball can fly in a tick; a ball that went farther jumped (a portal). */
    private final double longestStep;
    private final HeatGrid heat;
    private final Map<String, BallWatch> watches = new LinkedHashMap<>();
    private final Map<String, Integer> hits = new LinkedHashMap<>();
    private final List<Double> ballSeconds = new ArrayList<>();
    private final List<GameResult.Loss> losses = new ArrayList<>();
    private final List<GameResult.Jam> jams = new ArrayList<>();

    GameTally(Board board, double dt, HeatGrid heat) {
        this.board = board;
        this.dt = dt;
        this.heat = heat;
        this.jamTicks = Math.round(JAM_SECONDS / dt);
        this.longestStep = Board.MAX_SPEED * dt;
        for (Gizmo gizmo : board.gizmos()) {
            hits.put(gizmo.name(), 0);
        }
    }

    /** Reads the tick just run. */
    void afterTick() {
        long now = board.ticks();
        for (PlayEvent event : board.lastTick().events()) {
            if (event instanceof PlayEvent.Hit hit && hit.isRealImpact()
                    && hit.struck() instanceof TriggerSource.OfGizmo gizmo) {
                hits.merge(gizmo.gizmo(), 1, Integer::sum);
            } else if (event instanceof PlayEvent.Captured captured) {
                hits.merge(captured.absorber(), 1, Integer::sum);
                if (board.gameRules().isDrain(captured.absorber())) {
                    lost(captured.ball(), captured.absorber(), captured.at(), now);
                }
            } else if (event instanceof PlayEvent.Sunk sunk) {
                hits.merge(sunk.sink(), 1, Integer::sum);
                lost(sunk.ball(), sunk.sink(), sunk.at(), now);
                watches.remove(sunk.ball());
            } else if (event instanceof PlayEvent.Teleported teleported) {
                hits.merge(teleported.portal(), 1, Integer::sum);
            }
        }
        for (BallView ball : board.balls()) {
            if (!ball.isCaptured()) {
                watch(ball, now);
            } else {
                BallWatch held = watches.get(ball.name());
                if (held != null) {
                    held.lastX = Double.NaN;
                }
            }
        }
    }

    private void watch(BallView ball, long now) {
        BallWatch watch = watches.computeIfAbsent(ball.name(), name -> new BallWatch());
        if (watch.inPlaySince < 0) {
            watch.inPlaySince = now;
        }
        Vect at = ball.position();
        heat.addPath(watch.lastX, watch.lastY, at.x(), at.y(), longestStep);
        watch.lastX = at.x();
        watch.lastY = at.y();
        double dx = at.x() - watch.stillX;
        double dy = at.y() - watch.stillY;
        if (!(dx * dx + dy * dy <= STILL_DISTANCE * STILL_DISTANCE)) {
            watch.stillX = at.x();
            watch.stillY = at.y();
            watch.stillSince = now;
            watch.jamCounted = false;
        } else if (!watch.jamCounted && now - watch.stillSince >= jamTicks) {
            watch.jamCounted = true;
            jams.add(new GameResult.Jam((int) at.x(), (int) at.y()));
        }
    }

    private void lost(String ball, String place, Vect at, long now) {
        BallWatch watch = watches.get(ball);
        if (watch != null && watch.inPlaySince >= 0) {
            ballSeconds.add((now - watch.inPlaySince) * dt);
            watch.inPlaySince = -1;
            watch.stillX = Double.NaN;
        }
        Gizmo gizmo = board.gizmo(place).orElseThrow();
        double along = gizmo.width() >= gizmo.height() ? at.x() - gizmo.x() : at.y() - gizmo.y();
        losses.add(new GameResult.Loss(place, along));
    }

    /** The game as it stands: the balls still in play count with their time so far. */
    GameResult result() {
        long now = board.ticks();
        List<Double> seconds = new ArrayList<>(ballSeconds);
        for (BallWatch watch : watches.values()) {
            if (watch.inPlaySince >= 0) {
                seconds.add((now - watch.inPlaySince) * dt);
            }
        }
        return new GameResult(board.game().score(), now * dt, board.game().isOver(),
                seconds.stream().mapToDouble(Double::doubleValue).toArray(), hits, losses, jams);
    }
}
