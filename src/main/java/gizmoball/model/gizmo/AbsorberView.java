package gizmoball.model.gizmo;

/**
 * What views, controllers and the editor see of an absorber: its footprint, the balls it holds and, for a plunger,
 * how far it is pulled, read only.
 */
public sealed interface AbsorberView extends Gizmo permits Absorber {
    /** How far a plunger is pulled, 0 (at rest, or no plunger) to 1 (a full pull). */
    double pull();
}
