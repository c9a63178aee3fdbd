package gizmoball.sound;

/**
 * One sound to play: what it is, its pitch in Hz (clicks only; the others have their own) and its gain,
 * 0..1, the loudness before mixing. Cues are small immutable values, so the game's thread can hand them
 * to the audio thread without sharing any state.
 */
public record Cue(Kind kind, double pitchHz, double gain) {
    public enum Kind {
        /** A gizmo or wall hit by a ball. */
        CLICK,
        /** A flipper starting to swing. */
        SWISH,
        /** A ball captured by an absorber. */
        THUNK,
        /** An absorber firing a ball. */
        LAUNCH
    }

    public Cue {
        if (kind == null || !(gain >= 0 && gain <= 1) || !(pitchHz > 0 && pitchHz < Synth.SAMPLE_RATE / 2.0)) {
            throw new IllegalArgumentException("bad cue: " + kind + " " + pitchHz + " Hz, gain " + gain);
        }
    }
}
