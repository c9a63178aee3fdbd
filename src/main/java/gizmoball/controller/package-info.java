/**
 * Input into board calls: the game loop and speed (and watching a replay), key forwarding, file commands, the Game
 * menu's games (new game, game over, high scores, watch, save replay), modal pause, settings.
 */
package gizmoball.controller;
