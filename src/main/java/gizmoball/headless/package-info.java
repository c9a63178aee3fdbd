/** The headless runner: play a board for some ticks (to a key script) and write it out, or check a replay. */
package gizmoball.headless;
