/** Balls and the six-stage loop of play that moves them, run by the board one tick at a time. */
package gizmoball.model.loop;
