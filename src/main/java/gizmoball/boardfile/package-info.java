/**
 * Board files: reading (lexer, parser, loader through the board's own editing operations, line-numbered
 * errors), writing the canonical form atomically, and the vocabulary a file shares with the player: key codes
 * and their names ({@link gizmoball.boardfile.KeyCodes}), numbers ({@link gizmoball.boardfile.Decimals}), the
 * wording of file errors ({@link gizmoball.boardfile.FileErrors}).
 *
 * <p>May use: the model, java.awt.event.KeyEvent's key codes. No Swing.
 */
package gizmoball.boardfile;
