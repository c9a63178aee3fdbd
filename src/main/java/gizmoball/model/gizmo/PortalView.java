package gizmoball.model.gizmo;

import java.util.Optional;

import physics.Vect;

/** What views, controllers and the editor see of a portal: the side its mouth faces and its pair, read only. */
public sealed interface PortalView extends Gizmo permits Portal {
    /** The portal a ball entering this one's mouth leaves by; empty for none (then it is a wall). */
    Optional<String> pair();

    /** The unit vector out of its mouth: (0, -1) unturned, then (1, 0), (0, 1), (-1, 0) with each quarter turn. */
    Vect facing();
}
