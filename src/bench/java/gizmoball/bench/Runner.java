package gizmoball.bench;

import gizmoball.model.Board;
import physics.Vect;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/** Runs a scene with a method: timed (nothing but ticks and keys) or instrumented (every measure, every tick). */
final class Runner {

    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    /**
     * What an instrumented run saw. Energies are relative to the start energy; invariantTicks counts the
     * ticks the model's own Invariants flagged, -1 for the naive loop (to which they do not apply).
     */
    record Accuracy(List<Vect> finalPositions, double energyDrift, double maxEnergyRise, Probe.Tally faults,
                    long invariantTicks, double apexError) {}

    private Runner() {
    }

    static Stepper prepare(Scene scene, Method method, boolean spatialIndex) {
        Board board = scene.board().get();
        return method.loop() == Loop.NAIVE ? new NaiveStepper(board) : new ModelStepper(board, method.loop(), spatialIndex);
    }

    /** CPU time of this thread, in nanoseconds, to run the whole scene once (board building excluded). */
    static long cpuNanos(Scene scene, Method method, boolean spatialIndex) {
        Stepper stepper = prepare(scene, method, spatialIndex);
        KeyScript.Player keys = scene.keys().player(method.dt());
        long ticks = scene.ticks(method);
        double dt = method.dt();
        long start = THREADS.getCurrentThreadCpuTime();
        for (long i = 0; i < ticks; i++) {
            keys.beforeTick(stepper, i);
            stepper.tick(dt);
        }
        return THREADS.getCurrentThreadCpuTime() - start;
    }

    /**
     * Median over several samples of the CPU time of one run. The first run is untimed (it lets the JIT
     * settle on this path) and calibrates how many runs make a sample last at least {@code minSampleNanos},
     * so that short scenes are not measured at the timer's granularity.
     */
    static long medianCpuNanos(Scene scene, Method method, boolean spatialIndex, int samples, long minSampleNanos) {
        long first = Math.max(1, cpuNanos(scene, method, spatialIndex));
        long repetitions = Math.max(1, (minSampleNanos + first - 1) / first);
        long[] times = new long[samples];
        for (int i = 0; i < samples; i++) {
            long total = 0;
            for (long r = 0; r < repetitions; r++) {
                total += cpuNanos(scene, method, spatialIndex);
            }
            times[i] = total / repetitions;
        }
        return median(times);
    }

    static long median(long[] values) {
        long[] sorted = values.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }

    /** Runs the scene checking everything after every tick. */
    static Accuracy measure(Scene scene, Method method) {
        Stepper stepper = prepare(scene, method, true);
        KeyScript.Player keys = scene.keys().player(method.dt());
        long ticks = scene.ticks(method);
        double dt = method.dt();
        double e0 = stepper.energy();
        double scale = Math.max(Math.abs(e0), 1e-300);
        double maxRise = 0;
        Probe.Tally faults = new Probe.Tally();
        long invariantTicks = 0;
        ApexTracker apex = new ApexTracker();
        for (long i = 0; i < ticks; i++) {
            keys.beforeTick(stepper, i);
            stepper.tick(dt);
            Probe.check(stepper, faults);
            if (stepper.checksModelInvariants() && !stepper.modelInvariantsHold()) {
                invariantTicks++;
            }
            double energy = stepper.energy();
            maxRise = Math.max(maxRise, (energy - e0) / scale);
            apex.observe(stepper.balls().get(0));
        }
        double apexError = scene.exactApexY().map(apex::worstError).orElse(Double.NaN);
        long invariants = stepper.checksModelInvariants() ? invariantTicks : -1;
        return new Accuracy(positions(stepper), (stepper.energy() - e0) / scale, maxRise, faults, invariants, apexError);
    }

    static List<Vect> positions(Stepper stepper) {
        List<Vect> positions = new ArrayList<>();
        for (BallState b : stepper.balls()) {
            positions.add(b.position());
        }
        return positions;
    }

    /** Mean distance between corresponding balls. */
    static double meanDistance(List<Vect> a, List<Vect> b) {
        double sum = 0;
        for (int i = 0; i < a.size(); i++) {
            sum += Math.sqrt(a.get(i).distanceSquared(b.get(i)));
        }
        return sum / a.size();
    }

    /**
     * Heights of the turning points at the top of a ball's flight (y downward: vertical velocity turns
     * from negative to non-negative), taken as the lowest y seen during each rise.
     */
    private static final class ApexTracker {
        private final List<Double> apexes = new ArrayList<>();
        private double risingMin = Double.POSITIVE_INFINITY;
        private boolean rising;

        void observe(BallState ball) {
            double y = ball.position().y();
            if (ball.velocity().y() < 0) {
                rising = true;
                risingMin = Math.min(risingMin, y);
            } else if (rising) {
                rising = false;
                apexes.add(Math.min(risingMin, y));
                risingMin = Double.POSITIVE_INFINITY;
            }
        }

        /** Largest distance of an apex from the exact one; NaN when the ball never turned over. */
        double worstError(double exact) {
            return apexes.stream().mapToDouble(a -> Math.abs(a - exact)).max().orElse(Double.NaN);
        }
    }
}
