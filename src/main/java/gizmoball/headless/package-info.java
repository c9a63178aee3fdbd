/**
 * The headless runner ({@code gizmoball --headless}): load a board, run N ticks, write the board.
 *
 * <p>May use: the model and boardfile. No AWT, no Swing.
 */
package gizmoball.headless;
