package gizmoball.model.gizmo;

import physics.Circle;

/** What views, controllers and the editor see of an accelerator: its circle and its factor, read only. */
public sealed interface AcceleratorView extends Gizmo permits Accelerator {
    /** How many times faster a ball leaves than it came (up to the speed limit). */
    double factor();

    /** Its circle: centred in its cell, radius 0.5. */
    Circle circle();
}
