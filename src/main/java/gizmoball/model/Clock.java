package gizmoball.model;

/**
 * The board's two clocks: simulated seconds, which the loop moves on (delayed actions fall due by it), and ticks,
 * which games, key scripts and replays count in. Both start at 0 with the board and again when it is cleared.
 */
final class Clock {
    private double time;
    private long ticks;

    double time() {
        return time;
    }

    long ticks() {
        return ticks;
    }

    void advance(double dt) {
        time += dt;
    }

    void tickDone() {
        ticks++;
    }

    void reset() {
        time = 0;
        ticks = 0;
    }

    void copyFrom(Clock source) {
        time = source.time;
        ticks = source.ticks;
    }
}
