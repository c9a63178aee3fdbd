/** Games as data: key scripts, scripted play, replay files and the JSON report of a game. */
package gizmoball.replay;
