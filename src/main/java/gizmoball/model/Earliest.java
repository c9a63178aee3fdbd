package gizmoball.model;

/** Keeps the earliest collision offered within a time limit; near-ties go to circles (segment ends, corners). */
final class Earliest {
    /** Collisions this close in time count as simultaneous. */
    static final double TIE = 1e-12;

    private final double limit;
    /** The earliest offer so far (ball null: none); its {@link Collision} is made only when asked for. */
    private double time;
    private Ball ball;
    private Contact contact;
    private boolean circle;
    private Collision collision;

    Earliest(double limit) {
        this.limit = limit;
    }

    void offer(double time, Ball ball, Contact contact, boolean isCircle) {
        if (!(time >= 0 && time <= limit)) {
            return;   // also drops NaN and infinity
        }
        boolean better = this.ball == null
                || time < this.time - TIE
                || (time <= this.time + TIE && isCircle && !circle);
        if (better) {
            this.time = time;
            this.ball = ball;
            this.contact = contact;
            this.circle = isCircle;
            this.collision = null;
        }
    }

    /** Offers later than this are dropped. */
    double limit() {
        return ball == null ? limit : Math.min(limit, time + TIE);
    }

    /** The earliest offer, or null. */
    Collision collision() {
        if (collision == null && ball != null) {
            collision = new Collision(time, ball, contact);
        }
        return collision;
    }

    boolean isCircle() {
        return circle;
    }
}
