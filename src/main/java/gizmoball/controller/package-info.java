/**
 * What turns the player's commands into changes of the session and the model while the game runs: the game
 * loop and its speed, key forwarding to the board's bindings, the File menu's commands, the pause under modal
 * dialogs, the settings that stick.
 *
 * <p>May use: the model, the session, boardfile, and the view only as the place it reports to and opens dialogs
 * over (the view never imports this package). Build mode's logic is {@code gizmoball.editor}.
 */
package gizmoball.controller;
