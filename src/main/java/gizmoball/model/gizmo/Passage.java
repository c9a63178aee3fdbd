package gizmoball.model.gizmo;

import physics.Vect;

/**
 * A ball's way through a portal: the portal it enters and the pair it leaves by, named, and its centre and velocity
 * as it leaves ({@link Portal#passage}). The loop moves the ball by it without asking which kind it met.
 */
public record Passage(String entry, String exit, Vect centre, Vect velocity) {
}
