package physics;

/**
 * The test oracle: the gap between a moving ball and a turning obstacle computed in the world frame, by turning
 * the obstacle itself (independent of the library's rotating-frame search), and the first contact found by
 * dense time sampling plus bisection.
 */
final class WorldGap {
    /** Samples of the foresight window; the oracle can miss only contacts shallower than its sampling step. */
    static final int SAMPLES = 20_000;

    private final LineSegment segment;
    private final Circle circle;
    private final Vect pivot;
    private final double w;
    private final Circle ball;
    private final Vect velocity;

    private WorldGap(LineSegment segment, Circle circle, Vect pivot, double w, Circle ball, Vect velocity) {
        this.segment = segment;
        this.circle = circle;
        this.pivot = pivot;
        this.w = w;
        this.ball = ball;
        this.velocity = velocity;
    }

    static WorldGap wall(LineSegment segment, Vect pivot, double w, Circle ball, Vect velocity) {
        return new WorldGap(segment, null, pivot, w, ball, velocity);
    }

    static WorldGap circle(Circle circle, Vect pivot, double w, Circle ball, Vect velocity) {
        return new WorldGap(null, circle, pivot, w, ball, velocity);
    }

    /**
     * Distance between the surfaces at time t (negative when overlapping): the obstacle's points are turned by
     * w t about the pivot in the world frame, in plain arithmetic (no library call, for speed and independence).
     */
    double at(double t) {
        double cos = Math.cos(w * t);
        double sin = Math.sin(w * t);
        double cx = ball.getCenter().x() + velocity.x() * t;
        double cy = ball.getCenter().y() + velocity.y() * t;
        if (segment == null) {
            double qx = turnedX(circle.getCenter(), cos, sin);
            double qy = turnedY(circle.getCenter(), cos, sin);
            return Math.hypot(cx - qx, cy - qy) - circle.getRadius() - ball.getRadius();
        }
        double ax = turnedX(segment.p1(), cos, sin);
        double ay = turnedY(segment.p1(), cos, sin);
        double bx = turnedX(segment.p2(), cos, sin);
        double by = turnedY(segment.p2(), cos, sin);
        double dx = bx - ax;
        double dy = by - ay;
        double s = Math.max(0, Math.min(1, ((cx - ax) * dx + (cy - ay) * dy) / (dx * dx + dy * dy)));
        return Math.hypot(cx - ax - s * dx, cy - ay - s * dy) - ball.getRadius();
    }

    /**
     * For a wall: how far the foot of the perpendicular from the ball's centre lies beyond the nearer end of the
     * turned segment at time t (0 when it lies on the segment), and, in {@link #faceGap}, the ball's distance from
     * the segment's line minus its radius.
     */
    double footBeyond(double t) {
        return face(t)[0];
    }

    double faceGap(double t) {
        return face(t)[1];
    }

    private double[] face(double t) {
        double cos = Math.cos(w * t);
        double sin = Math.sin(w * t);
        double cx = ball.getCenter().x() + velocity.x() * t;
        double cy = ball.getCenter().y() + velocity.y() * t;
        double ax = turnedX(segment.p1(), cos, sin);
        double ay = turnedY(segment.p1(), cos, sin);
        double dx = turnedX(segment.p2(), cos, sin) - ax;
        double dy = turnedY(segment.p2(), cos, sin) - ay;
        double length = Math.hypot(dx, dy);
        double along = ((cx - ax) * dx + (cy - ay) * dy) / length;
        double across = ((cy - ay) * dx - (cx - ax) * dy) / length;
        return new double[] {Math.max(0, Math.max(-along, along - length)), Math.abs(across) - ball.getRadius()};
    }

    /** Whether the ball's centre is where a face contact leads: foot on the segment, within r of its line. */
    private boolean onFace(double t) {
        double[] face = face(t);
        return face[0] == 0 && face[1] <= 0;
    }

    /**
     * The first face contact in [0, horizon], the meaning of timeUntilWallCollision turning: the first sampled
     * time at which the centre has come onto the face region over its long side (not over an end, which is an
     * end contact), refined by bisection; infinity if none. The ball must start off the face region.
     */
    double firstFaceContact(double horizon) {
        double previous = 0;
        for (int i = 1; i <= SAMPLES; i++) {
            double t = horizon * i / SAMPLES;
            if (onFace(t)) {
                double lo = previous;
                double hi = t;
                for (int k = 0; k < 60; k++) {
                    double mid = 0.5 * (lo + hi);
                    if (onFace(mid)) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                if (faceGap(lo) > 0) {
                    return hi; // came in over the long side
                }
                // Came in over an end: skip the samples it stays on the face region.
                while (i < SAMPLES && onFace(horizon * (i + 1) / SAMPLES)) {
                    i++;
                }
                t = horizon * i / SAMPLES;
            }
            previous = t;
        }
        return Double.POSITIVE_INFINITY;
    }

    /** How a contact that touches at time 0 goes on, as the oracle sees it. */
    enum Start {
        /** The ball is inside the obstacle (for a wall: on its face, foot on the segment) at every probe time. */
        CLOSING,
        /** The ball is clear of the obstacle (for a wall: of its face) at every probe time. */
        OPENING,
        /** Neither: the scene is too close to call and is not used. */
        UNCLEAR
    }

    /** Probe times of {@link #start}: {@value #START_PROBES} halvings from {@link #START_HORIZON} s. */
    static final double START_HORIZON = 1e-3;
    static final int START_PROBES = 11;

    /**
     * Whether a ball touching the obstacle at time 0 closes on it or leaves it: the gap (for a wall, the face's:
     * the foot must lie on the segment) at the times START_HORIZON / 2^k, k &lt; START_PROBES (1e-3 s down to
     * about 1e-6 s), must have one sign at all of them. Those times are long enough for a quadratic start to show
     * far above rounding, and short enough that the motion cannot turn back in between.
     */
    Start start() {
        int inside = 0;
        for (int k = 0; k < START_PROBES; k++) {
            double t = START_HORIZON / (1 << k);
            if (segment == null ? at(t) < 0 : footBeyond(t) == 0 && faceGap(t) < 0) {
                inside++;
            }
        }
        return inside == START_PROBES ? Start.CLOSING : inside == 0 ? Start.OPENING : Start.UNCLEAR;
    }

    /**
     * The speed at which the ball closes on the obstacle at time t, relative to the obstacle's surface where they
     * touch (negative when leaving): for a wall along the normal at the foot on its line, for a circle along the
     * line of centres. It is what a reflection off the moving surface acts on.
     */
    double closingSpeed(double t) {
        double cos = Math.cos(w * t);
        double sin = Math.sin(w * t);
        double cx = ball.getCenter().x() + velocity.x() * t;
        double cy = ball.getCenter().y() + velocity.y() * t;
        double fx;
        double fy;
        if (segment == null) {
            fx = turnedX(circle.getCenter(), cos, sin);
            fy = turnedY(circle.getCenter(), cos, sin);
        } else {
            double ax = turnedX(segment.p1(), cos, sin);
            double ay = turnedY(segment.p1(), cos, sin);
            double dx = turnedX(segment.p2(), cos, sin) - ax;
            double dy = turnedY(segment.p2(), cos, sin) - ay;
            double s = ((cx - ax) * dx + (cy - ay) * dy) / (dx * dx + dy * dy);
            fx = ax + s * dx;
            fy = ay + s * dy;
        }
        // The surface point's velocity w J (point - pivot); along the normal, the circle's centre stands for it.
        double surfaceX = -w * (fy - pivot.y());
        double surfaceY = w * (fx - pivot.x());
        double nx = cx - fx;
        double ny = cy - fy;
        double length = Math.hypot(nx, ny);
        return -((velocity.x() - surfaceX) * nx + (velocity.y() - surfaceY) * ny) / length;
    }

    /**
     * The first time in [0, horizon] at which the ball is more than {@code depth} inside the obstacle (for a wall:
     * its face, foot on the segment), from dense sampling refined by bisection; infinity if never.
     */
    double firstDeeperThan(double depth, double horizon) {
        double previous = 0;
        for (int i = 1; i <= SAMPLES; i++) {
            double t = horizon * i / SAMPLES;
            if (deeperThan(depth, t)) {
                double lo = previous;
                double hi = t;
                for (int k = 0; k < 60; k++) {
                    double mid = 0.5 * (lo + hi);
                    if (deeperThan(depth, mid)) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                return hi;
            }
            previous = t;
        }
        return Double.POSITIVE_INFINITY;
    }

    private boolean deeperThan(double depth, double t) {
        return segment == null ? at(t) < -depth : footBeyond(t) == 0 && faceGap(t) < -depth;
    }

    private double turnedX(Vect p, double cos, double sin) {
        return pivot.x() + (p.x() - pivot.x()) * cos - (p.y() - pivot.y()) * sin;
    }

    private double turnedY(Vect p, double cos, double sin) {
        return pivot.y() + (p.x() - pivot.x()) * sin + (p.y() - pivot.y()) * cos;
    }

    /** The first sampled time in [0, horizon] with gap &le; 0, refined by bisection; infinity if none. */
    double firstContact(double horizon) {
        double previous = 0;
        for (int i = 1; i <= SAMPLES; i++) {
            double t = horizon * i / SAMPLES;
            if (at(t) <= 0) {
                double lo = previous;
                double hi = t;
                for (int k = 0; k < 60; k++) {
                    double mid = 0.5 * (lo + hi);
                    if (at(mid) <= 0) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                return hi;
            }
            previous = t;
        }
        return Double.POSITIVE_INFINITY;
    }
}
