package gizmoball.model.gizmo;

import java.util.List;
import java.util.Optional;

/**
 * What views, controllers and the editor see of an absorber: its footprint, the balls it holds and, for a plunger,
 * how far it is pulled, read only.
 */
public sealed interface AbsorberView extends Gizmo permits Absorber {
    /** The names of the balls it holds, longest-held first (a copy). */
    List<String> held();

    /** How it launches when it is a plunger; empty for an absorber that fires at once. */
    Optional<Plunger> plunger();

    /** How far a plunger is pulled, 0 (at rest, or no plunger) to 1 (a full pull). */
    double pull();
}
