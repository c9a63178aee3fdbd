package gizmoball.model.gizmo;

import java.util.List;

/** What views, controllers and the editor see of an absorber: its footprint and the balls it holds, read only. */
public sealed interface AbsorberView extends Gizmo permits Absorber {
    /** The names of the balls it holds, longest-held first (a copy). */
    List<String> held();
}
