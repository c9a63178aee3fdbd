package gizmoball.model.loop;

/** Keeps the earliest collision offered within a time limit; near-ties go to circles (segment ends, corners). */
final class Earliest {
    private double limit;
    /** The earliest offer so far (ball null: none). */
    private double time;
    private Ball ball;
    private Contact contact;
    private boolean circle;

    Earliest(double limit) {
        this.limit = limit;
    }

    /** Nothing offered yet, offers later than {@code newLimit} dropped: as new, for a search that asks many times. */
    void reset(double newLimit) {
        limit = newLimit;
        ball = null;
        contact = null;
    }

    void offer(double time, Ball ball, Contact contact, boolean isCircle) {
        if (!(time >= 0 && time <= limit)) {
            return;   // also drops NaN and infinity
        }
        if (better(time, isCircle, this.ball == null, this.time, circle)) {
            this.time = time;
            this.ball = ball;
            this.contact = contact;
            this.circle = isCircle;
        }
    }

    /**
     * Whether an offer at {@code time} beats the best so far ({@code none}: there is none yet): sooner by more than
     * {@link Tolerances#TIME_TIE}, or a circle tied with a segment.
     */
    private static boolean better(double time, boolean isCircle, boolean none, double bestTime, boolean bestCircle) {
        return none || time < bestTime - Tolerances.TIME_TIE
                || (time <= bestTime + Tolerances.TIME_TIE && isCircle && !bestCircle);
    }

    /** Offers later than this are dropped. */
    double limit() {
        return ball == null ? limit : Math.min(limit, time + Tolerances.TIME_TIE);
    }

    /** What the earliest offer meets, or null: none (read with {@link #time()}). */
    Contact contact() {
        return ball == null ? null : contact;
    }

    /** Seconds until the earliest offer, when there is one ({@link #contact()} not null). */
    double time() {
        return time;
    }

    boolean isCircle() {
        return circle;
    }
}
