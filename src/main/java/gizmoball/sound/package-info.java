/** Sound cues synthesised in code and played on an audio thread of their own. */
package gizmoball.sound;
