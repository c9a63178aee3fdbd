package gizmoball.sound;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.gizmo.GizmoKind;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** The synthesized sounds and their mix, measured on the buffers: no audio device is involved. */
class SoundSynthesisTest {

    @Test
    void aClickIsLouderTheFasterTheImpact() {
        double slow = rms(Synth.render(Sounds.gizmoHit(GizmoKind.CIRCLE, 3).orElseThrow()));
        double medium = rms(Synth.render(Sounds.gizmoHit(GizmoKind.CIRCLE, 12).orElseThrow()));
        double fast = rms(Synth.render(Sounds.gizmoHit(GizmoKind.CIRCLE, 35).orElseThrow()));
        assertThat(slow).isPositive();
        assertThat(medium).isGreaterThan(slow);
        assertThat(fast).isGreaterThan(medium);
    }

    @Test
    void aBallSettlingMakesNoSound() {
        assertThat(Sounds.gizmoHit(GizmoKind.SQUARE, 0.3)).isEmpty();
        assertThat(Sounds.wallHit(0)).isEmpty();
    }

    @Test
    void eachKindOfGizmoClicksAtItsOwnPitch() {
        assertThat(Arrays.stream(GizmoKind.values()).map(Sounds::pitchOf).distinct().count())
                .isEqualTo(GizmoKind.values().length - 1); // the two flippers sound alike
        // The pitch is in the sound, not only in the cue: count zero crossings of the tone.
        double squareHz = zeroCrossingHz(Synth.render(Sounds.gizmoHit(GizmoKind.SQUARE, 40).orElseThrow()));
        double circleHz = zeroCrossingHz(Synth.render(Sounds.gizmoHit(GizmoKind.CIRCLE, 40).orElseThrow()));
        assertThat(circleHz / squareHz).isCloseTo(880.0 / 520, within(0.15));
    }

    @Test
    void oneSoundPassesTheMixerUnchanged() {
        float[] launch = Synth.render(Sounds.fire());
        Mixer mixer = new Mixer();
        mixer.add(launch);
        float[] mixed = new float[launch.length];
        mixer.render(mixed);
        assertThat(mixed).containsExactly(launch, within(0f)); // exactly, but 0 + -0 is +0
        assertThat(mixer.isIdle()).isTrue();
    }

    @Test
    void fiftySimultaneousHitsAtFullSpeedNeverClip() {
        Mixer mixer = new Mixer();
        GizmoKind[] kinds = GizmoKind.values();
        for (int i = 0; i < 50; i++) {
            mixer.add(Synth.render(Sounds.gizmoHit(kinds[i % kinds.length], 60).orElseThrow()));
        }
        float[] block = new float[256];
        byte[] pcm = new byte[512];
        double peak = 0;
        int blocks = 0;
        while (!mixer.isIdle()) {
            mixer.render(block);
            Mixer.toPcm16(block, pcm);
            for (int i = 0; i < block.length; i++) {
                peak = Math.max(peak, Math.abs(block[i]));
                int s = (short) ((pcm[2 * i] & 0xff) | (pcm[2 * i + 1] << 8));
                assertThat(Math.abs(s)).isLessThan(Short.MAX_VALUE);
            }
            blocks++;
        }
        assertThat(blocks).isPositive();
        // Unlimited, the sum would peak far above full scale; limited, it is loud but below the ceiling.
        assertThat(peak).isLessThanOrEqualTo(Mixer.CEILING + 1e-6).isGreaterThan(Mixer.CEILING / 2);
    }

    @Test
    void everySoundStaysWithinFullScale() {
        for (Cue cue : new Cue[] {Sounds.flipperSwing(), Sounds.capture(), Sounds.fire(),
                Sounds.ballHit(500).orElseThrow(), Sounds.wallHit(500).orElseThrow()}) {
            float[] samples = Synth.render(cue);
            assertThat(samples).isNotEmpty();
            for (float s : samples) {
                assertThat(Math.abs(s)).isLessThan(1f);
            }
        }
    }

    private static double rms(float[] samples) {
        double sum = 0;
        for (float s : samples) {
            sum += s * s;
        }
        return Math.sqrt(sum / samples.length);
    }

    /** The frequency of the dominant tone in the first 20 ms, from its sign changes. */
    private static double zeroCrossingHz(float[] samples) {
        int n = Synth.SAMPLE_RATE / 50;
        int crossings = 0;
        for (int i = Synth.SAMPLE_RATE / 500 + 1; i < n; i++) {
            if ((samples[i - 1] < 0) != (samples[i] < 0)) {
                crossings++;
            }
        }
        return crossings / 2.0 / ((n - Synth.SAMPLE_RATE / 500) / (double) Synth.SAMPLE_RATE);
    }
}
