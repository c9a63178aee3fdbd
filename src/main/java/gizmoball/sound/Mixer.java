package gizmoball.sound;

import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.Iterator;

/**
 * Sums the sounds playing at once into one stream and keeps it below full scale. Sounds are added
 * whole and mixed block by block as the audio device asks for samples.
 * <p>
 * The sum goes through a peak limiter: the gain follows the loudest recent sample, dropping at once
 * (in the same sample, so no sample ever exceeds {@link #CEILING}) and recovering over
 * {@link #RELEASE_SECONDS}. A single hit passes unchanged; fifty at once are turned down, not clipped.
 * Not thread-safe: the audio thread owns it.
 */
public final class Mixer {
    /** The limiter's ceiling, below full scale so that rounding to 16 bits can never wrap. */
    public static final double CEILING = 0.9;
    /** More voices than this and the oldest is dropped: a storm of hits is still one loud rattle. */
    static final int MAX_VOICES = 32;
    private static final double RELEASE_SECONDS = 0.08;
    private static final double RELEASE = Math.exp(-1 / (RELEASE_SECONDS * Synth.SAMPLE_RATE));

    private final ArrayDeque<Voice> voices = new ArrayDeque<>();
    /** The envelope of the peak level above the ceiling, as the factor the mix is turned down by. */
    private double overshoot = 1;

    private static final class Voice {
        final float[] samples;
        int next;

        Voice(float[] samples) {
            this.samples = samples;
        }
    }

    public void add(float[] samples) {
        if (voices.size() == MAX_VOICES) {
            voices.removeFirst();
        }
        voices.addLast(new Voice(samples));
    }

    public boolean isIdle() {
        return voices.isEmpty();
    }

    /** Fills {@code out} with the next {@code out.length} samples of the mix (silence once every sound ended). */
    public void render(float[] out) {
        Arrays.fill(out, 0);
        for (Iterator<Voice> it = voices.iterator(); it.hasNext();) {
            Voice v = it.next();
            int n = Math.min(out.length, v.samples.length - v.next);
            for (int i = 0; i < n; i++) {
                out[i] += v.samples[v.next + i];
            }
            v.next += n;
            if (v.next == v.samples.length) {
                it.remove();
            }
        }
        for (int i = 0; i < out.length; i++) {
            double level = Math.abs(out[i]) / CEILING;
            overshoot = Math.max(level, 1 + (overshoot - 1) * RELEASE);
            out[i] = (float) (out[i] / overshoot);
        }
    }

    /** 16-bit signed little-endian PCM of {@code samples}, as the audio line takes it. */
    public static void toPcm16(float[] samples, byte[] out) {
        for (int i = 0; i < samples.length; i++) {
            int s = Math.round(samples[i] * Short.MAX_VALUE);
            out[2 * i] = (byte) s;
            out[2 * i + 1] = (byte) (s >> 8);
        }
    }
}
