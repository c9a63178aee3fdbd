/**
 * High scores without Swing: each board's top ten ({@link gizmoball.highscore.HighScoreTable}, name, score, date and
 * the game's replay), keyed by the board's content as built, kept per user with java.util.prefs beside the settings
 * ({@link gizmoball.highscore.HighScoreStore}). May use: model, boardfile, replay, Gson, the JDK; no AWT, no Swing.
 */
package gizmoball.highscore;
