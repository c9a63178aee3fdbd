package gizmoball.model.gizmo;

import physics.Vect;

/** What views, controllers and the editor see of a flipper: where it is and how it swings, read only. */
public sealed interface FlipperView extends Gizmo, BarView permits Flipper {
    /** Centre of the round end at the pivot. */
    @Override
    Vect pivot();

    /** Centre of the other round end, at the current angle. */
    @Override
    Vect tip();

    /** Radius of both round ends. */
    @Override
    double radius();

    /** Degrees swung from rest, 0..90. */
    double angleFromRest();

    /** True while the flipper is up or swinging up. */
    boolean isActive();

    /** True while it swings toward a stop. */
    boolean isMoving();

    /** True while a jammed ball holds the flipper short of its stop. */
    boolean isStalled();
}
