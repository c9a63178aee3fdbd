/** The headless runner: load a board, run it for some ticks, write it out. */
package gizmoball.headless;
