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
    /** The most plays, however busy the compilers stay. */
    static final int MOST_PLAYS = 12;
    /** Plays where the JVM does not say how long it compiled. */
    static final int PLAYS_UNMEASURED = 4;

    private static final CompilationMXBean COMPILER = ManagementFactory.getCompilationMXBean();

    private CompilerWarmUp() {
    }

    /**
     * Runs {@code play} until one run of it leaves the compilers quiet ({@link #QUIET}), at most {@link #MOST_PLAYS}
     * times; returns how many times it ran.
     */
    static int play(Runnable play) {
        boolean measured = COMPILER != null && COMPILER.isCompilationTimeMonitoringSupported();
        for (int plays = 1; ; plays++) {
            long compiledBefore = measured ? COMPILER.getTotalCompilationTime() : 0;
            long start = System.nanoTime();
            play.run();
            double wallMillis = (System.nanoTime() - start) / 1e6;
            boolean quiet = measured
                    ? COMPILER.getTotalCompilationTime() - compiledBefore < QUIET * wallMillis
                    : plays >= PLAYS_UNMEASURED;
            if (quiet || plays == MOST_PLAYS) {
                return plays;
            }
        }
    }
}
