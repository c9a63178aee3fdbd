package gizmoball.model.gizmo;

import physics.Vect;

/**
 * What views see of a gizmo whose bar play turns about a pivot (a flipper, a spinner), read only: enough to draw the
 * bar turned part of the way between two ticks without asking which kind it is.
 */
public interface BarView {
    String name();

    /** The point the bar turns about. */
    Vect pivot();

    /** The centre of the round end that the bar points to from its pivot, at the angle now (a spinner's second end). */
    Vect tip();

    /** Radius of the bar's round ends. */
    double radius();
}
