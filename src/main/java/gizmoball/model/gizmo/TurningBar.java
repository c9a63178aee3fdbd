package gizmoball.model.gizmo;

import physics.LineSegment;
import physics.Vect;

/**
 * A bar with round ends that play turns about a pivot (a flipper, a spinner): what the two share. The ends' radius and
 * the bar's bounce; the stall a jammed ball holds it in; the turning, a step of {@code dt} seconds each kind takes in
 * its own way ({@link #turn}) whenever it moves; and the shape at the angle now, made when first asked after a turn.
 * The members are for the board and its loop, not for views.
 */
abstract sealed class TurningBar extends GizmoBase implements MovingShape permits Flipper, Spinner {
    /** Radius of both round ends: half the bar's width. */
    static final double RADIUS = 0.25;
    /** Its {@link #reflectionCoefficient()}, still or turning. */
    private static final double REFLECTION = 0.95;

    /** Held where it is by a jammed ball until the ball has gone or it is sent the other way. */
    private boolean stalled;
    /**
     * The shape at the angle now, made when first asked after a turn (null till then): the loop turns every moving
     * bar at each collision of a tick, and asks the shape only of those a ball can reach.
     */
    private Shape currentShape;
    /**
     * The segment between its round ends' centres (circles 0 and 1 of every bar's shape) in {@code coreOf}, the shape
     * it was made for: a bar stalled by a sleeping ball is measured against the balls by it at every tick.
     */
    private LineSegment core;
    private Shape coreOf;

    TurningBar(String name, GizmoKind kind, int x, int y) {
        super(name, kind, x, y);
    }

    /** A copy of its common state, the stall and the shape now with it (for deep copies). */
    TurningBar(TurningBar other) {
        super(other);
        this.stalled = other.stalled;
        this.currentShape = other.currentShape;
    }

    @Override
    public double reflectionCoefficient() {
        return REFLECTION;
    }

    /** Radius of both round ends. */
    public double radius() {
        return RADIUS;
    }

    /** Whether it turns now: it would ({@link #turns}) and no jammed ball holds it. */
    @Override
    public boolean isMoving() {
        return !stalled && turns();
    }

    /** Whether it would turn now if no ball held it: a flipper short of the stop it swings to, a spinner running. */
    abstract boolean turns();

    /** True while a jammed ball holds it. */
    @Override
    public boolean isStalled() {
        return stalled;
    }

    /** A ball jammed between the bar and something else stops it where it is. */
    @Override
    public void stall() {
        stalled = true;
    }

    /** The ball that held it has gone, or it was sent the other way: it turns on. */
    @Override
    public void release() {
        stalled = false;
    }

    /** Turns for {@code dt} seconds as its kind turns, if it moves; its shape is made again when next asked. */
    @Override
    public void advance(double dt) {
        if (!isMoving() || dt <= 0) {
            return;
        }
        turn(dt);
        currentShape = null;
    }

    /** Its angle moves on by {@code dt} seconds of turning (it moves, and {@code dt} is positive). */
    abstract void turn(double dt);

    @Override
    public Shape shape() {
        if (currentShape == null) {
            currentShape = shapeNow();
        }
        return currentShape;
    }

    /** Its angle was set, or its place changed: the shape now is made at once. */
    final void reshaped() {
        currentShape = shapeNow();
    }

    /** The shape at its angle now. */
    abstract Shape shapeNow();

    /** Signed distance from p to the bar: a capsule about the segment between its round ends' centres. */
    @Override
    public double signedDistance(Vect p) {
        Shape now = shape();
        if (coreOf != now) {
            core = new LineSegment(now.circles().get(0).getCenter(), now.circles().get(1).getCenter());
            coreOf = now;
        }
        return Solids.toCapsule(core, RADIUS, p);
    }
}
