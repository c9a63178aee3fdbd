/** Architecture tests: the package arrows, the physics API the game may use, and the read-only model views see. */
package gizmoball.api;
