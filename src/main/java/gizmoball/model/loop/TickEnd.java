package gizmoball.model.loop;

import java.util.ArrayList;
import java.util.List;

import physics.Vect;

/**
 * Stage 6 of a tick (docs/design.md, "The tick"): what the tick did, as it was at its end, kept until the next tick
 * ends. The board's own listeners read its events in place; the {@link TickReport} is made only for whoever asks, so
 * that play makes none (docs/design.md, "What a tick allocates").
 */
final class TickEnd {
    private final StepContext step;
    /** The tick's time in each stage, by {@link Stage#ordinal()}: the loop's array, which it clears at its start. */
    private final long[] nanos;
    private double time;
    private int collisions;
    private int zeroTimeCollisions;
    private int simultaneousCollisions;
    private int awake;
    private int asleep;
    private GuardCounts guards = GuardCounts.NONE;
    private TickEvents events;
    private List<BallReport> balls = List.of();

    TickEnd(StepContext step, long[] nanos) {
        this.step = step;
        this.nanos = nanos;
    }

    /** The tick is over: what it did, the redraw before it timed if {@code timing}. */
    void take(boolean timing) {
        LoopView view = step.view;
        double lookAhead = view.nextCollisionLookAhead();
        // Without the look-ahead no ball is reported: no list is made for none, and the balls are not looked through.
        List<BallReport> reports = lookAhead > 0 ? new ArrayList<>() : List.of();
        List<Ball> all = view.balls();
        for (int b = 0; lookAhead > 0 && b < all.size(); b++) {
            Ball ball = all.get(b);
            if (!ball.isCaptured()) {
                reports.add(ballReport(ball, lookAhead));
            }
        }
        balls = reports;
        nanos[Stage.REDRAWING.ordinal()] = timing ? view.lastRedrawNanos() : 0;
        time = view.time();
        collisions = step.collisions;
        zeroTimeCollisions = step.zeroTimeCollisions;
        simultaneousCollisions = step.simultaneousCollisions;
        awake = step.awake.size();
        asleep = step.asleepNow();
        guards = step.guards();
        events = step.actions.closeTickEvents();
    }

    /** The report of the tick, made anew; its events' records are the caller's to keep. */
    TickReport report() {
        return new TickReport(time, StageTimes.of(nanos), collisions, zeroTimeCollisions, simultaneousCollisions,
                awake, asleep, guards, events.copy(), balls);
    }

    TickEvents events() {
        return events;
    }

    GuardCounts guards() {
        return guards;
    }

    private BallReport ballReport(Ball ball, double lookAhead) {
        BallReport.BallState state = ball.isAsleep() ? BallReport.BallState.ASLEEP
                : ball.contacts().isEmpty() ? BallReport.BallState.FLYING : BallReport.BallState.CONTACT;
        double in = Double.POSITIVE_INFINITY;
        Vect at = null;
        if (!ball.isAsleep()) {
            Earliest earliest = step.detector.againstScene(ball, lookAhead);
            List<Ball> others = step.view.balls();
            for (int b = 0; b < others.size(); b++) {
                Ball other = others.get(b);
                if (other != ball && !other.isCaptured()) {
                    step.detector.againstBall(ball, other, lookAhead, earliest);
                }
            }
            if (earliest.contact() != null) {
                in = earliest.time();
                at = ball.position().plus(ball.velocity().times(in));
            }
        }
        return new BallReport(ball.name(), ball.position(), ball.velocity(), state, in, at);
    }
}
