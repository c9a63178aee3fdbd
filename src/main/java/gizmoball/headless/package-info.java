/**
 * The headless runner: play a board for some ticks (to a key script) and write it out, check a replay, or run the
 * board lab on a board.
 */
package gizmoball.headless;
