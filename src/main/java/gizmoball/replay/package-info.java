/**
 * Games as data, without Swing: key scripts ({@link gizmoball.replay.KeyScript}, a key down or up with its tick),
 * playing a board to a script ({@link gizmoball.replay.ScriptedPlay}), replay files (the board as built, the key
 * script, the ticks and the final score: {@link gizmoball.replay.Replay}, {@link gizmoball.replay.ReplayFiles}) and
 * the JSON summary of a game ({@link gizmoball.replay.GameReport}). A game is a function of its board and its key
 * script, so a replay reproduces it bit for bit. May use: model, boardfile, Gson; no AWT, no Swing.
 */
package gizmoball.replay;
