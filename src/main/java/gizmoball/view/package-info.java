/** The Swing views of play: the window, the board view, the status line, dialogs and help. */
package gizmoball.view;
