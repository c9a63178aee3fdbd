/** High scores: each board's top ten with the games' replays, kept per user beside the settings. */
package gizmoball.highscore;
