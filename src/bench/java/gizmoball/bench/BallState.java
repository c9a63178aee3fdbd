package gizmoball.bench;

import physics.Vect;

/** A ball as the measures see it, whichever loop moved it. */
record BallState(Vect position, Vect velocity, double radius, boolean captured) {}
