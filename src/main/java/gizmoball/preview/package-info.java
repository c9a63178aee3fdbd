/** Build mode's aim preview: where a ball being placed or moved will go, played on a copy of the board. */
package gizmoball.preview;
