package gizmoball.model.gizmo;

import java.util.List;

import physics.Vect;

/** What views, controllers and the editor see of a spinner: its bar, its angle and how it turns, read only. */
public sealed interface SpinnerView extends Gizmo, BarView permits Spinner {
    /** The centre of its box, which it turns about. */
    @Override
    Vect pivot();

    /** The bar's direction in radians from +x toward +y (clockwise on the screen), in [0, 2 pi). */
    double angle();

    /** The centres of its two round ends at the current angle, the second the {@link #tip} its angle points to. */
    List<Vect> ends();

    /** Radius of both round ends (half the bar's width). */
    @Override
    double radius();

    /** Its speed and way in turns per second: positive clockwise on the screen, negative anticlockwise. */
    double turnsPerSecond();

    /** False once told to stop, until told to start. */
    boolean isRunning();

    /** Turning now: running and not stalled. */
    boolean isMoving();

    /** True while a jammed ball holds it. */
    boolean isStalled();
}
