package gizmoball.model.loop;

import physics.Circle;
import physics.LineSegment;
import physics.Vect;

/**
 * Tests on the components of whether a moving ball may meet a still line or circle within a time: where they say no,
 * the detector's answer would be "no collision", so it is found without asking physics-lib or making the ball's
 * vectors (docs/design.md, "Detection asks only about what can be reached"). Each errs only toward yes, by
 * {@link Tolerances#REACH_MARGIN}, far above rounding.
 */
final class Approach {
    private Approach() {
    }

    /**
     * Whether a ball at (cx, cy) moving at (vx, vy) may touch the segment's whole line within {@code within} seconds
     * while closing on it. Where it does not, the API's time is beyond {@code within} by {@link
     * Tolerances#REACH_MARGIN} at least, or the ball does not close, which {@link CollisionDetector#closesOnSegment}
     * then refuses (a ball moving away from a line, or along it, stays on its side). A centre on the line is asked.
     */
    static boolean mayMeetLine(LineSegment segment, double cx, double cy, double vx, double vy, double within) {
        Vect p1 = segment.p1();
        Vect p2 = segment.p2();
        double nx = p1.y() - p2.y();   // a normal of the line, |n| its length
        double ny = p2.x() - p1.x();
        double side = (cx - p1.x()) * nx + (cy - p1.y()) * ny;
        double toward = vx * nx + vy * ny;
        if (side > 0 ? toward >= 0 : side < 0 && toward <= 0) {
            return false;   // moving away from the line, or along it
        }
        double length = Math.sqrt(nx * nx + ny * ny);
        return Math.abs(side) - Arena.BALL_RADIUS * length
                <= Math.abs(toward) * within + Tolerances.REACH_MARGIN * length;
    }

    /**
     * Whether two balls may touch within {@code within} seconds while closing, the first's centre (dx, dy) from the
     * second's and moving at (rx, ry) relative to it: near enough for their speed, closing, and on a line of relative
     * motion that passes the other centre within touch. The pair test asks it first ({@link
     * CollisionDetector#againstBall}); the schedule asks it of the filed balls' slots before it asks the detector.
     */
    static boolean mayMeetBall(double dx, double dy, double rx, double ry, double within) {
        double gap = Math.sqrt(dx * dx + dy * dy) - 2 * Arena.BALL_RADIUS;
        double speed = Math.sqrt(rx * rx + ry * ry);   // a plain square root, as speedOf's
        return !(gap > speed * within + Tolerances.REACH_MARGIN) && dx * rx + dy * ry < 0
                && !(Math.abs(dx * ry - dy * rx) > (2 * Arena.BALL_RADIUS + Tolerances.REACH_MARGIN) * speed);
    }

    /**
     * Whether a ball at (cx, cy) moving at (vx, vy) may touch the circle within {@code within} seconds while closing
     * on it, as for a pair of balls: closing, near enough for its speed, and on a line that passes the centre within
     * touch. Where it does not, the API's answer is beyond {@code within}, or {@link CollisionDetector#closingOnCircle}
     * refuses it.
     */
    static boolean mayMeetCircle(Circle circle, double cx, double cy, double vx, double vy, double within) {
        double dx = cx - circle.getCenter().x();
        double dy = cy - circle.getCenter().y();
        if (!(dx * vx + dy * vy < 0)) {
            return false;   // not closing: the distance cannot fall
        }
        double touch = circle.getRadius() + Arena.BALL_RADIUS;
        double speed = Math.sqrt(vx * vx + vy * vy);
        return Math.sqrt(dx * dx + dy * dy) - touch <= speed * within + Tolerances.REACH_MARGIN
                && Math.abs(dx * vy - dy * vx) <= (touch + Tolerances.REACH_MARGIN) * speed;
    }
}
