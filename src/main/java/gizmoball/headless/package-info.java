/**
 * The headless runner: load a board, run it for some ticks (to a key script), write it out, with the game's report
 * and replay; or play a replay file again and check its score.
 */
package gizmoball.headless;
