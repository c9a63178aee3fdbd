/**
 * The Swing views of play: the window, the board view, the status line, the score panel and launch hint, dialogs
 * (game over, high scores) and help.
 */
package gizmoball.view;
