package gizmoball.model;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.List;

/**
 * Stage 3 over the whole board: the earliest collision of any awake ball within the time left in the tick. It keeps
 * each ball's earliest collision with the scene (walls and gizmos) and with the other balls, in seconds since the
 * tick began, so that after a collision only the balls it changed are asked again, not every ball against
 * everything. What a collision changes is forgotten by the loop: the balls involved, or everything when a
 * trigger, a capture, a launch, a wake-up or a held flipper changes the scene. Ball pairs come from a
 * {@link BallGrid}, so a ball is asked only about the balls it can reach.
 */
final class CollisionSchedule {
    /** A ball's earliest known collision: {@code at} seconds since the tick began; none when collision is null. */
    private record Known(double at, Collision collision, boolean circle) {
    }

    private final CollisionDetector detector;
    /** Each free ball's known collisions, by its slot ({@link Ball#slot()}); null: not known, ask again. */
    private Known[] withScene = new Known[0];
    private Known[] withBalls = new Known[0];
    /**
     * By slot, the slots whose known ball collision has been with that ball (some since replaced): forgetting a ball
     * looks only at those, not at every ball.
     */
    private int[][] pointedAtBy = new int[0][];
    private int[] pointedAtCount = new int[0];
    private int filed;
    private final BallGrid grid;
    private final List<Ball> nearby = new ArrayList<>();
    /** When the grid was filled, and the highest speed of any ball since: how stale its positions can be. */
    private double filedAt;
    private double fastest;

    CollisionSchedule(CollisionDetector detector, BallGrid grid) {
        this.detector = detector;
        this.grid = grid;
    }

    /** Files every free ball (awake or asleep) where it is now, {@code elapsed} seconds into the tick. */
    void file(Collection<Ball> free, double elapsed) {
        grid.clear();
        filedAt = elapsed;
        fastest = 0;
        filed = 0;
        withScene = new Known[free.size()];
        withBalls = new Known[free.size()];
        pointedAtBy = new int[free.size()][];
        pointedAtCount = new int[free.size()];
        for (Ball ball : free) {
            ball.setSlot(filed++);
            grid.add(ball);
            sped(ball);
        }
    }

    /** A ball's velocity changed: positions may go stale faster. */
    void sped(Ball ball) {
        fastest = Math.max(fastest, CollisionDetector.speedBound(detector.motion(ball)));
    }

    /** The earliest collision of the awake balls within the window, {@code elapsed} seconds into the tick. */
    Collision next(List<Ball> awake, double elapsed, double window) {
        int n = awake.size();
        for (int i = 0; i < n; i++) {
            Ball ball = awake.get(i);
            int slot = ball.slot();
            if (withScene[slot] == null) {
                withScene[slot] = known(detector.againstScene(ball, window), elapsed);
            }
            if (withBalls[slot] == null) {
                askAgainstBalls(ball, elapsed, window);
            }
        }
        Earliest earliest = new Earliest(window);
        for (int i = 0; i < n; i++) {   // only now: asking about a ball may have told an earlier one of a sooner pair
            int slot = awake.get(i).slot();
            offer(earliest, withScene[slot], elapsed, window);
            offer(earliest, withBalls[slot], elapsed, window);
        }
        return earliest.collision();
    }

    /** The ball's velocity or position changed other than by moving on: ask again about it. */
    void forget(Ball ball) {
        if (ball.isCaptured()) {
            return;   // filed no more: the capture filed the free balls afresh
        }
        int slot = ball.slot();
        withScene[slot] = null;
        withBalls[slot] = null;
        int[] pointing = pointedAtBy[slot];
        for (int k = 0; k < pointedAtCount[slot]; k++) {
            Known known = withBalls[pointing[k]];
            if (known != null && known.collision() != null && partner(known) == ball) {
                withBalls[pointing[k]] = null;
            }
        }
        pointedAtCount[slot] = 0;
    }

    void forgetAll() {
        Arrays.fill(withScene, null);
        Arrays.fill(withBalls, null);
        Arrays.fill(pointedAtCount, 0);
    }

    private static Ball partner(Known known) {
        return ((Contact.OtherBall) known.collision().contact()).other();
    }

    /** Files a ball's earliest known ball collision, noting it with its partner. */
    private void knowWithBalls(int slot, Known known) {
        withBalls[slot] = known;
        if (known.collision() == null) {
            return;
        }
        int partner = partner(known).slot();
        int[] pointing = pointedAtBy[partner];
        if (pointing == null || pointing.length == pointedAtCount[partner]) {
            int grown = Math.max(4, 2 * pointedAtCount[partner]);
            pointing = pointing == null ? new int[grown] : Arrays.copyOf(pointing, grown);
            pointedAtBy[partner] = pointing;
        }
        pointing[pointedAtCount[partner]++] = slot;
    }

    /**
     * The ball against every ball it can reach in the window; a pair sooner than what the other ball knew becomes
     * the other's too. A sleeping ball is a still target; it never asks.
     */
    private void askAgainstBalls(Ball ball, double elapsed, double window) {
        Earliest earliest = new Earliest(window);
        double speed = CollisionDetector.speedBound(detector.motion(ball));
        double reach = 2 * Board.BALL_RADIUS + (speed + fastest) * window + fastest * (elapsed - filedAt) + 1e-6;
        nearby.clear();
        grid.near(ball.position().x(), ball.position().y(), reach, nearby);
        for (Ball other : nearby) {
            if (other == ball || other.isCaptured()) {
                continue;
            }
            Earliest pair = new Earliest(window);
            detector.againstBall(other, ball, window, pair);
            Collision found = pair.collision();
            if (found == null) {
                continue;
            }
            earliest.offer(found.time(), ball, new Contact.OtherBall(other), true);
            Known theirs = withBalls[other.slot()];
            if (theirs != null && (theirs.collision() == null || elapsed + found.time() < theirs.at())) {
                knowWithBalls(other.slot(), new Known(elapsed + found.time(), found, true));
            }
        }
        knowWithBalls(ball.slot(), known(earliest, elapsed));
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
