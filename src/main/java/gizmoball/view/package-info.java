/** The Swing views of play: the window, the board, the status line, the score panel, dialogs and help. */
package gizmoball.view;
