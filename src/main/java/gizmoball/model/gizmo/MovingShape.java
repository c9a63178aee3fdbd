package gizmoball.model.gizmo;

import physics.Vect;

/**
 * A gizmo whose shape turns about a pivot during play, as the loop sees it (docs/design.md, "Moving shapes"):
 * detection asks physics-lib's rotating methods about its shape now, turning at {@link #angularVelocity()} for
 * {@link #timeToStop()}; contacts, sleep, wake and the cluster solve take it as kinematic (it gives velocity and
 * takes none); a ball it cannot push out of a pocket stalls it. A flipper is one (it stops at its limits); a shape
 * that turns for ever says so with an infinite {@link #timeToStop()}. The members are for the board and its loop, not
 * for views.
 */
public interface MovingShape {
    String name();

    GizmoKind kind();

    /** The footprint, whole cells: every point the shape can sweep lies within it. */
    int x();

    int y();

    int width();

    int height();

    double reflectionCoefficient();

    /** Records that it was hit, {@code time} seconds into play. */
    void markTriggered(double time);

    /** The shape at its angle now. */
    Shape shape();

    /** The point it turns about. */
    Vect pivot();

    /** Whether it is turning now: not at a stop, not stalled. */
    boolean isMoving();

    /** Signed angular velocity in radians per second in the library's sense (+x toward +y); 0 when not moving. */
    double angularVelocity();

    /** Seconds until it stops turning of itself; {@code Double.POSITIVE_INFINITY} for a shape that never does. */
    double timeToStop();

    /** The shape where it stops, {@link #timeToStop()} from now; asked only when that time is finite. */
    Shape shapeAtStop();

    /** Whether circle {@code index} of its shape is centred on the pivot: it turns in place, still to a ball. */
    boolean turnsInPlace(int index);

    /** Turns for {@code dt} seconds, stopping exactly where it stops of itself. */
    void advance(double dt);

    /** A jammed ball holds it where it is: it does not move until released or sent another way. */
    void stall();

    boolean isStalled();

    /** What stalled it has gone: it moves on. */
    void release();

    /** Signed distance from a point to its shape now: negative inside. */
    double signedDistance(Vect p);
}
