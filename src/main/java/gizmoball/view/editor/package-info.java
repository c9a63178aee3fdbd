/**
 * Build mode's views: the palette, the properties panel, the Edit menu, the overlay drawn over the board
 * (previews, selection, connections), the edge popup of Key Connect, and the board input that turns mouse and
 * key events on the board view into editor calls.
 *
 * <p>May use: gizmoball.view, the editor, the model, the session, boardfile's key names and numbers. Never the
 * controllers or the application.
 */
package gizmoball.view.editor;
