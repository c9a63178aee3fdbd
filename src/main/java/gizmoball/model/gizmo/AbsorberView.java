package gizmoball.model.gizmo;

/**
 * What views, controllers and the editor see of an absorber, read only: what every gizmo says, of which the balls it
 * holds ({@link #held}), its plunger ({@link #plunger}) and how far that is pulled ({@link #pull}) are its own.
 */
public sealed interface AbsorberView extends Gizmo permits Absorber {
}
