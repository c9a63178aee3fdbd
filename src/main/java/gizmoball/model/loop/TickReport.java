package gizmoball.model.loop;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;

/**
 * What the last tick did, read-only, as stage 6 found it (docs/design.md, "The tick"). The board makes it when it is
 * first asked for after a tick, for play itself reads the tick's events in place ({@link TickEvents}); it is the
 * asker's to keep.
 *
 * @param stageNanos time spent in each stage; stages 2-5 repeat within a tick and are summed. The redrawing stage
 *                   is the observers' time, which is known only after they return: it is the previous tick's.
 * @param collisions collisions resolved (zero-time ones included)
 * @param zeroTimeCollisions collisions in a chain: resolved at the very moment of an earlier one of the same ball (or
 *                   of the ball it meets), the bounces among a ball's contacts within one collision included
 * @param simultaneousCollisions collisions at the moment of another ball's that are no chain: balls apart (a board's
 *                   identical columns) colliding at the same instant
 * @param balls      the free balls, with their next collision when the board's look-ahead is on, else empty
 */
public record TickReport(double time, Map<Stage, Long> stageNanos, int collisions, int zeroTimeCollisions,
                         int simultaneousCollisions,
                         int ballsAwake, int ballsAsleep, GuardCounts guards, List<PlayEvent> events,
                         List<BallReport> balls) {
    public static final TickReport NONE = new TickReport(0, new EnumMap<>(Stage.class), 0, 0, 0, 0, 0,
            GuardCounts.NONE, List.of(), List.of());

    public TickReport {
        stageNanos = StageTimes.of(stageNanos);   // every stage, read-only
        events = List.copyOf(events);
        balls = List.copyOf(balls);
    }
}
