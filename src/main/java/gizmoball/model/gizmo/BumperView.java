package gizmoball.model.gizmo;

import java.util.List;

import physics.Circle;
import physics.Vect;

/** What views, controllers and the editor see of a square, circle or triangle bumper: its outline, read only. */
public sealed interface BumperView extends Gizmo permits Bumper {
    /** Polygon corners in board coordinates in the current rotation (square 4, triangle 3); empty for a circle. */
    List<Vect> outline();

    /** The circle of a CIRCLE bumper: centred in its cell, radius 0.5. */
    Circle circle();
}
