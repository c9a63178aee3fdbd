/** Input into board calls: the game loop and its speed, keys, file commands, the Game menu, pause, settings. */
package gizmoball.controller;
