package gizmoball.model.gizmo;

import physics.Vect;

/**
 * The quarter turn a gizmo's bar sweeps when its key raises it (a flipper's), as a player judges what a swing can
 * strike ({@link Gizmo#sweep}): the pivot, the unit vectors from it along the bar at rest and raised, and how far
 * from the pivot the bar reaches, its round end included.
 */
public record Sweep(Vect pivot, Vect rest, Vect up, double reach) {
}
