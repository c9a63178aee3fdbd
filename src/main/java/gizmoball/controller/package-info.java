/** Input into board calls: the game loop and speed, key forwarding, file commands, modal pause, settings. */
package gizmoball.controller;
