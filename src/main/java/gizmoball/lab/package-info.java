/**
 * The board lab: players that play a board through its public API (an autoplayer that flips, an idle player that
 * only launches), many games of a board played in parallel, and what they show (scores, seconds per ball, drains,
 * hits, jams, where the balls went).
 */
package gizmoball.lab;
