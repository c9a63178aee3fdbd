/**
 * The Swing views: the window with its menus and status line, the board view (painter, overlays, transform),
 * the dialogs and help pages. A view shows the model and the session and asks for what the player wants
 * through interfaces the application gives it ({@link gizmoball.view.GameWindow.Commands}).
 *
 * <p>May use: the model, the session, the editor, boardfile's key names and numbers. Never the controllers or
 * the application: those build the views and are told by them.
 */
package gizmoball.view;
