/** The rules of a game on a board: what a hit scores, balls per game, drains, the game in progress. */
package gizmoball.model.game;
