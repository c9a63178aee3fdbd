/**
 * Sound: cues synthesised in code and mixed on an audio thread of their own, so that play never waits for the
 * audio device, and a missing device is reported once.
 *
 * <p>May use: the model (what was hit) and javax.sound. No Swing.
 */
package gizmoball.sound;
