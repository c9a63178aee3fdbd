package gizmoball.model;

/** Keeps the earliest collision offered within a time limit; near-ties go to circles (segment ends, corners). */
final class Earliest {
    /** Collisions this close in time count as simultaneous. */
    static final double TIE = 1e-12;

    private final double limit;
    private Collision collision;
    private boolean circle;

    Earliest(double limit) {
        this.limit = limit;
    }

    void offer(double time, Ball ball, Contact contact, boolean isCircle) {
        if (!(time >= 0 && time <= limit)) {
            return;   // also drops NaN and infinity
        }
        boolean better = collision == null
                || time < collision.time() - TIE
                || (time <= collision.time() + TIE && isCircle && !circle);
        if (better) {
            collision = new Collision(time, ball, contact);
            circle = isCircle;
        }
    }

    /** Offers later than this are dropped. */
    double limit() {
        return collision == null ? limit : Math.min(limit, collision.time() + TIE);
    }

    /** The earliest offer, or null. */
    Collision collision() {
        return collision;
    }

    boolean isCircle() {
        return circle;
    }
}
