/**
 * The state of one window: the one {@link gizmoball.model.Board} every view observes, the design play starts
 * from, the file it came from, whether it has unsaved changes, and the mode (play or build).
 *
 * <p>May use: the model. No Swing; the views read it and the controllers change it.
 */
package gizmoball.session;
