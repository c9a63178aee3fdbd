/** The board without Swing: gizmos, balls, wiring, editing and play, behind {@link gizmoball.model.Board}. */
package gizmoball.model;
