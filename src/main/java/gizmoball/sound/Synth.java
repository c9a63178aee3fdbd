package gizmoball.sound;

import java.util.SplittableRandom;

/**
 * Synthesizes each cue as a short mono buffer of samples in -1..1 at {@link #SAMPLE_RATE}: no audio files.
 * Every sound is a few decaying partials or filtered noise; the same cue always gives the same samples
 * (the noise is seeded), so that the tests can measure them.
 */
public final class Synth {
    public static final int SAMPLE_RATE = 44_100;

    private static final double CLICK_SECONDS = 0.06;
    private static final double CLICK_DECAY = 0.012;
    private static final double SWISH_SECONDS = 0.14;
    private static final double THUNK_SECONDS = 0.18;
    private static final double THUNK_HZ = 70;
    private static final double LAUNCH_SECONDS = 0.25;
    private static final double LAUNCH_FROM_HZ = 180;
    private static final double LAUNCH_TO_HZ = 720;
    /** A single sound at full gain peaks here, leaving the mixer headroom for a few at once. */
    private static final double PEAK = 0.6;

    private Synth() {
    }

    public static float[] render(Cue cue) {
        return switch (cue.kind()) {
            case CLICK -> click(cue.pitchHz(), cue.gain());
            case SWISH -> swish(cue.gain());
            case THUNK -> thunk(cue.gain());
            case LAUNCH -> launch(cue.gain());
        };
    }

    /** A knock: a sine and its inharmonic overtone, decaying within tens of milliseconds, over a tick of noise. */
    private static float[] click(double hz, double gain) {
        float[] out = new float[frames(CLICK_SECONDS)];
        SplittableRandom noise = new SplittableRandom(1);
        for (int i = 0; i < out.length; i++) {
            double t = (double) i / SAMPLE_RATE;
            double envelope = Math.exp(-t / CLICK_DECAY);
            double tone = 0.7 * Math.sin(2 * Math.PI * hz * t) + 0.2 * Math.sin(2 * Math.PI * 2.76 * hz * t);
            double tick = t < 0.002 ? 0.4 * (noise.nextDouble() * 2 - 1) * (1 - t / 0.002) : 0;
            out[i] = (float) (PEAK * gain * (envelope * tone + tick) / 1.3);
        }
        return out;
    }

    /**
     * Air: noise through a one-pole low-pass whose cutoff sweeps down, swelling and fading. The filter's
     * output is a running weighted mean of noise in -1..1, so it stays within -1..1 too.
     */
    private static float[] swish(double gain) {
        float[] out = new float[frames(SWISH_SECONDS)];
        SplittableRandom noise = new SplittableRandom(2);
        double low = 0;
        for (int i = 0; i < out.length; i++) {
            double phase = (double) i / out.length;
            double cutoffHz = 4000 - 3000 * phase;
            double a = 1 - Math.exp(-2 * Math.PI * cutoffHz / SAMPLE_RATE);
            low += a * ((noise.nextDouble() * 2 - 1) - low);
            double envelope = Math.sin(Math.PI * phase);
            out[i] = (float) (PEAK * gain * envelope * low);
        }
        return out;
    }

    /** A low, damped drop in pitch: a ball landing in the absorber. */
    private static float[] thunk(double gain) {
        float[] out = new float[frames(THUNK_SECONDS)];
        double phase = 0;
        for (int i = 0; i < out.length; i++) {
            double t = (double) i / SAMPLE_RATE;
            phase += 2 * Math.PI * THUNK_HZ * (1 + 1.5 * Math.exp(-t / 0.02)) / SAMPLE_RATE;
            double envelope = Math.exp(-t / 0.045) * Math.min(1, t / 0.002);
            out[i] = (float) (PEAK * gain * envelope * Math.sin(phase));
        }
        return out;
    }

    /** A rising sweep with a little noise: the absorber's spring letting go. */
    private static float[] launch(double gain) {
        float[] out = new float[frames(LAUNCH_SECONDS)];
        SplittableRandom noise = new SplittableRandom(3);
        double phase = 0;
        for (int i = 0; i < out.length; i++) {
            double x = (double) i / out.length;
            phase += 2 * Math.PI * (LAUNCH_FROM_HZ + (LAUNCH_TO_HZ - LAUNCH_FROM_HZ) * x * x) / SAMPLE_RATE;
            double envelope = Math.min(1, x * 20) * (1 - x);
            double sample = 0.8 * Math.sin(phase) + 0.2 * (noise.nextDouble() * 2 - 1);
            out[i] = (float) (PEAK * gain * envelope * sample);
        }
        return out;
    }

    private static int frames(double seconds) {
        return (int) Math.round(seconds * SAMPLE_RATE);
    }
}
