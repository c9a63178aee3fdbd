package gizmoball.model.loop;

/**
 * The choice of {@link CollisionSchedule#next} among the near-ties of the earliest known collision: those no later than
 * it by {@link Tolerances#TIME_TIE}, of which the first circle offered is taken, else the first. Each offer is a
 * ball's slot and whether it is its collision with the scene or with balls; times are from now, rounding kept in the
 * window.
 */
final class NearTies {
    private double elapsed;
    private double window;
    /** The latest time from now of a near-tie. */
    private double lastTie;
    private int slot;
    private boolean withScene;
    private double time;
    private boolean circle;

    /** Nothing offered yet, {@code elapsed} seconds into the tick, for the window; the earliest is at {@code earliest}. */
    void reset(double elapsedNow, double windowNow, double earliest) {
        elapsed = elapsedNow;
        window = windowNow;
        lastTie = fromNow(earliest) + Tolerances.TIME_TIE;
        slot = -1;
        circle = false;
    }

    /** From now, the rounding kept in the window: the time a known collision at {@code at} is offered with. */
    private double fromNow(double at) {
        return Math.min(Math.max(0, at - elapsed), window);
    }

    /** Whether a known collision at {@code at} (seconds since the tick began) is a near-tie of the earliest. */
    boolean isNearTie(double at) {
        // fromNow(at) <= lastTie without its min and max: lastTie is positive, so max(0, d) <= lastTie is d <= lastTie
        return at != Double.POSITIVE_INFINITY && (at - elapsed <= lastTie || window <= lastTie);
    }

    /** The slot of the offer taken (-1: none yet). */
    int slot() {
        return slot;
    }

    /** Whether the offer taken is the slot's collision with the scene (not with balls). */
    boolean withScene() {
        return withScene;
    }

    /** Seconds from now until the offer taken. */
    double time() {
        return time;
    }

    /** Whether a circle is taken: no later offer can be. */
    boolean foundCircle() {
        return circle;
    }

    /** A known collision at {@code at} seconds since the tick began; taken if it is the first near-tie or circle. */
    void offer(int offered, boolean scene, double at, boolean isCircle) {
        if (!isNearTie(at) || slot >= 0 && (circle || !isCircle)) {
            return;
        }
        slot = offered;
        withScene = scene;
        time = fromNow(at);
        circle = isCircle;
    }
}
