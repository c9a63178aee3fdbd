package gizmoball.bench;

import java.lang.management.CompilationMXBean;
import java.lang.management.ManagementFactory;

/**
 * Throw-away plays of a board until the JIT compilers have caught up with its paths, so that what the benchmark times
 * afterwards is the code a long game runs, not the compilers at work. One play was not enough: on 2 cores, the board of
 * 200 balls in play cost about 350 us a tick in its second play, 240-390 in its fourth and fifth and 200-210 in most
 * plays from its ninth on; the compilers worked as long as each of its first plays lasted, and 5% of the ninth.
 */
final class CompilerWarmUp {
    /** A play during which the compilers worked less than this part of its wall time ends the warm-up. */
    static final double QUIET = 0.05;
    /** The most plays, however busy the compilers stay, once they have lasted {@link #LEAST_MILLIS}. */
    static final int MOST_PLAYS = 12;
    /**
     * Milliseconds the plays last at least. A board measured with classes of its own ({@link Isolated}) has every
     * method compiled for it afresh: a method runs in the compiler's profiling tier until it has been called thousands
     * of times, with the compilers idle, so that 3 quiet plays of one ball among five bumpers (30 ms) measured 2.5 us
     * a tick, 5 times what it costs compiled.
     */
    static final double LEAST_MILLIS = 3_000;
    /** Plays where the JVM does not say how long it compiled. */
    static final int PLAYS_UNMEASURED = 4;

    private static final CompilationMXBean COMPILER = ManagementFactory.getCompilationMXBean();

    private CompilerWarmUp() {
    }

    /**
     * Runs {@code play} for at least {@link #LEAST_MILLIS}, until one run of it leaves the compilers quiet
     * ({@link #QUIET}) or it has run {@link #MOST_PLAYS} times; returns how many times it ran.
     */
    static int play(Runnable play) {
        boolean measured = COMPILER != null && COMPILER.isCompilationTimeMonitoringSupported();
        long first = System.nanoTime();
        for (int plays = 1; ; plays++) {
            long compiledBefore = measured ? COMPILER.getTotalCompilationTime() : 0;
            long start = System.nanoTime();
            play.run();
            double wallMillis = (System.nanoTime() - start) / 1e6;
            boolean quiet = measured
                    ? COMPILER.getTotalCompilationTime() - compiledBefore < QUIET * wallMillis
                    : plays >= PLAYS_UNMEASURED;
            if ((quiet || plays >= MOST_PLAYS) && (System.nanoTime() - first) / 1e6 >= LEAST_MILLIS) {
                return plays;
            }
        }
    }
}
