package gizmoball.model;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Stage 3 over the whole board: the earliest collision of any free ball within the time left in the tick. It keeps
 * each ball's earliest collision with the scene (walls and gizmos) and with the other balls, in seconds since the
 * tick began, so that after a collision only the balls it changed are asked again, not every ball against
 * everything. What a collision changes is forgotten by the loop: the balls involved, or everything when a
 * trigger, a capture, a launch or a held flipper changes the scene.
 */
final class CollisionSchedule {
    /** A ball's earliest known collision: {@code at} seconds since the tick began; none when collision is null. */
    private record Known(double at, Collision collision, boolean circle) {
    }

    private final CollisionDetector detector;
    private final Map<Ball, Known> withScene = new HashMap<>();
    private final Map<Ball, Known> withBalls = new HashMap<>();
    private List<Ball> freeBalls = List.of();

    CollisionSchedule(CollisionDetector detector) {
        this.detector = detector;
    }

    /** The earliest collision within the window, {@code elapsed} seconds into the tick; null if none. */
    Collision next(List<Ball> free, double elapsed, double window) {
        if (!free.equals(freeBalls)) {
            forgetAll();
            freeBalls = List.copyOf(free);
        }
        for (Ball ball : free) {
            withScene.computeIfAbsent(ball, b -> known(detector.againstScene(b, window), elapsed));
        }
        for (Ball ball : free) {
            if (!withBalls.containsKey(ball)) {
                askAgainstBalls(ball, free, elapsed, window);
            }
        }
        Earliest earliest = new Earliest(window);
        for (Ball ball : free) {
            offer(earliest, withScene.get(ball), elapsed, window);
            offer(earliest, withBalls.get(ball), elapsed, window);
        }
        return earliest.collision();
    }

    /** The ball's velocity or position changed other than by moving on: ask again about it. */
    void forget(Ball ball) {
        withScene.remove(ball);
        withBalls.remove(ball);
        withBalls.values().removeIf(known -> known.collision() != null
                && ((Contact.OtherBall) known.collision().contact()).other() == ball);
    }

    void forgetAll() {
        withScene.clear();
        withBalls.clear();
    }

    /** The ball against every other; a pair sooner than what another ball knew becomes that ball's too. */
    private void askAgainstBalls(Ball ball, List<Ball> free, double elapsed, double window) {
        Earliest earliest = new Earliest(window);
        for (Ball other : free) {
            if (other == ball) {
                continue;
            }
            Earliest pair = new Earliest(window);
            detector.againstBall(other, ball, window, pair);
            Collision found = pair.collision();
            if (found == null) {
                continue;
            }
            earliest.offer(found.time(), ball, new Contact.OtherBall(other), true);
            Known theirs = withBalls.get(other);
            if (theirs != null && (theirs.collision() == null || elapsed + found.time() < theirs.at())) {
                withBalls.put(other, new Known(elapsed + found.time(), found, true));
            }
        }
        withBalls.put(ball, known(earliest, elapsed));
    }

    private static Known known(Earliest earliest, double elapsed) {
        Collision collision = earliest.collision();
        return collision == null ? new Known(Double.POSITIVE_INFINITY, null, false)
                : new Known(elapsed + collision.time(), collision, earliest.isCircle());
    }

    /** Offers a known collision with its time from now, rounding of the bookkeeping kept within the window. */
    private static void offer(Earliest earliest, Known known, double elapsed, double window) {
        if (known.collision() == null) {
            return;
        }
        double time = Math.min(Math.max(0, known.at() - elapsed), window);
        earliest.offer(time, known.collision().ball(), known.collision().contact(), known.circle());
    }
}
