package physics;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.function.IntToDoubleFunction;

/**
 * A plain micro-benchmark, not a test: {@code gradle :physics-lib:benchmark} prints nanoseconds per call of every
 * public collision and reflection method of {@link Geometry}, then the ratio of each rotating method to its static
 * counterpart on the same scenes. Numbers depend on the machine and its load.
 * <p>
 * Each method runs over the same {@value #SCENES} flipper-sized scenes (fixed seed), so the branch predictor
 * cannot learn one answer. Each figure is the fastest of {@value #ROUNDS} timed rounds after a warm-up, timed in
 * the thread's CPU time: on a shared machine other processes only ever add time, to wall-clock time most.
 */
public final class GeometryBenchmark {
    private static final int SCENES = 256;
    private static final long SEED = 20261201L;
    private static final int ROUNDS = 9;
    /** Calls per round for the closed forms; the rotating searches get a twentieth of that. */
    private static final int CALLS = 400_000;
    private static final double FLIPPER_SPEED = Math.toRadians(1080);
    private static final ThreadMXBean CPU = ManagementFactory.getThreadMXBean();
    private static double sink;

    private GeometryBenchmark() {
    }

    /** One scene: a flipper-like segment and circle turning about the pivot, a ball near them, a second ball. */
    private record Scene(Vect pivot, LineSegment segment, Circle circle, Circle ball, Vect velocity,
                         Circle touchingFace, Circle touchingCircle, Circle other, Vect otherVelocity) {
    }

    public static void main(String[] args) {
        List<Scene> scenes = scenes();
        Scene[] s = scenes.toArray(new Scene[0]);
        Map<String, Double> ns = new LinkedHashMap<>();
        double w = FLIPPER_SPEED;
        // The floor under every figure: the loop, the scene lookup and the call through the lambda.
        measure(ns, "(loop overhead: one field read)", 1, i -> s[i].velocity.x());
        measure(ns, "timeUntilWallCollision", 1, i -> Geometry.timeUntilWallCollision(s[i].segment, s[i].ball,
                s[i].velocity));
        measure(ns, "timeUntilRotatingWallCollision", 20, i -> Geometry.timeUntilRotatingWallCollision(s[i].segment,
                s[i].pivot, w, s[i].ball, s[i].velocity));
        measure(ns, "timeUntilCircleCollision", 1, i -> Geometry.timeUntilCircleCollision(s[i].circle, s[i].ball,
                s[i].velocity));
        measure(ns, "timeUntilRotatingCircleCollision", 20, i -> Geometry.timeUntilRotatingCircleCollision(
                s[i].circle, s[i].pivot, w, s[i].ball, s[i].velocity));
        measure(ns, "timeUntilCircleCollision (point, roots)", 1, i -> Geometry.timeUntilCircleCollision(
                s[i].circle, s[i].ball.getCenter(), s[i].velocity).d1);
        measure(ns, "timeUntilBallBallCollision", 1, i -> Geometry.timeUntilBallBallCollision(s[i].ball,
                s[i].velocity, s[i].other, s[i].otherVelocity));
        measure(ns, "reflectWall", 1, i -> Geometry.reflectWall(s[i].segment, s[i].velocity).x());
        measure(ns, "reflectWall (coefficient)", 1, i -> Geometry.reflectWall(s[i].segment, s[i].velocity, 0.95).x());
        measure(ns, "reflectRotatingWall", 1, i -> Geometry.reflectRotatingWall(s[i].segment, s[i].pivot, w,
                s[i].touchingFace, s[i].velocity).x());
        measure(ns, "reflectRotatingWall (coefficient)", 1, i -> Geometry.reflectRotatingWall(s[i].segment,
                s[i].pivot, w, s[i].touchingFace, s[i].velocity, 0.95).x());
        measure(ns, "reflectCircle", 1, i -> Geometry.reflectCircle(s[i].circle.getCenter(),
                s[i].touchingCircle.getCenter(), s[i].velocity).x());
        measure(ns, "reflectCircle (coefficient)", 1, i -> Geometry.reflectCircle(s[i].circle.getCenter(),
                s[i].touchingCircle.getCenter(), s[i].velocity, 0.95).x());
        measure(ns, "reflectRotatingCircle", 1, i -> Geometry.reflectRotatingCircle(s[i].circle, s[i].pivot, w,
                s[i].touchingCircle, s[i].velocity).x());
        measure(ns, "reflectRotatingCircle (coefficient)", 1, i -> Geometry.reflectRotatingCircle(s[i].circle,
                s[i].pivot, w, s[i].touchingCircle, s[i].velocity, 0.95).x());
        measure(ns, "reflectBalls", 1, i -> Geometry.reflectBalls(s[i].ball.getCenter(), 1, s[i].velocity,
                s[i].other.getCenter(), 2, s[i].otherVelocity).v1.x());
        measure(ns, "applyReflectionCoeff", 1, i -> Geometry.applyReflectionCoeff(s[i].velocity,
                s[i].otherVelocity, 0.95).x());

        System.out.println();
        System.out.printf("%-40s %12s%n", "rotating / static", "ratio");
        ratio(ns, "timeUntilRotatingWallCollision", "timeUntilWallCollision");
        ratio(ns, "timeUntilRotatingCircleCollision", "timeUntilCircleCollision");
        ratio(ns, "reflectRotatingWall (coefficient)", "reflectWall (coefficient)");
        ratio(ns, "reflectRotatingCircle (coefficient)", "reflectCircle (coefficient)");
        System.out.println("(sink " + sink + ")");
    }

    /**
     * Balls within reach of a flipper of length 1.5-2.5 L with its pivot at an end, moving at up to 20 L/s
     * (some at rest); about half of the rotating queries hit within the default foresight.
     */
    private static List<Scene> scenes() {
        Random random = new Random(SEED);
        List<Scene> scenes = new ArrayList<>();
        while (scenes.size() < SCENES) {
            Vect pivot = new Vect(between(random, 0, 20), between(random, 0, 20));
            Vect along = new Vect(new Angle(between(random, 0, 2 * Math.PI)), between(random, 1.5, 2.5));
            LineSegment segment = new LineSegment(pivot, pivot.plus(along));
            Circle circle = new Circle(segment.p2(), 0.25);
            double radius = 0.25;
            Vect centre = pivot.plus(new Vect(new Angle(between(random, 0, 2 * Math.PI)), between(random, 0.8, 3)));
            Circle ball = new Circle(centre, radius);
            if (segmentDistance(segment, centre) <= radius || centre.distanceSquared(circle.getCenter()) <= 0.25) {
                continue; // a ball that starts clear of both
            }
            Vect velocity = random.nextInt(8) == 0 ? Vect.ZERO
                    : new Vect(new Angle(between(random, 0, 2 * Math.PI)), between(random, 1, 20));
            Vect foot = pivot.plus(along.times(between(random, 0.1, 0.9)));
            Vect normal = new Vect(-along.y(), along.x()).unitSize().times(random.nextBoolean() ? radius : -radius);
            Circle touchingFace = new Circle(foot.plus(normal), radius);
            Vect outward = new Vect(new Angle(between(random, 0, 2 * Math.PI)));
            Circle touchingCircle = new Circle(circle.getCenter().plus(outward.times(0.5)), radius);
            Circle other = new Circle(centre.plus(new Vect(new Angle(between(random, 0, 2 * Math.PI)),
                    between(random, 0.5, 6))), radius);
            Vect otherVelocity = new Vect(new Angle(between(random, 0, 2 * Math.PI)), between(random, 0, 20));
            scenes.add(new Scene(pivot, segment, circle, ball, velocity, touchingFace, touchingCircle, other,
                    otherVelocity));
        }
        return scenes;
    }

    private static double segmentDistance(LineSegment segment, Vect point) {
        Vect dir = segment.p2().minus(segment.p1());
        double s = Math.max(0, Math.min(1, point.minus(segment.p1()).dot(dir) / dir.dot(dir)));
        return Math.sqrt(point.distanceSquared(segment.p1().plus(dir.times(s))));
    }

    private static double between(Random random, double low, double high) {
        return low + (high - low) * random.nextDouble();
    }

    private static void measure(Map<String, Double> ns, String name, int slowdown, IntToDoubleFunction call) {
        int calls = CALLS / slowdown;
        double[] rounds = new double[ROUNDS];
        run(call, calls); // warm-up
        for (int round = 0; round < ROUNDS; round++) {
            long start = CPU.getCurrentThreadCpuTime();
            run(call, calls);
            rounds[round] = (CPU.getCurrentThreadCpuTime() - start) / (double) calls;
        }
        double fastest = Arrays.stream(rounds).min().orElseThrow();
        ns.put(name, fastest);
        System.out.printf("%-40s %9.1f ns/call%n", name, fastest);
    }

    private static void run(IntToDoubleFunction call, int calls) {
        double sum = 0;
        for (int i = 0; i < calls; i++) {
            sum += call.applyAsDouble(i & (SCENES - 1));
        }
        sink += sum;
    }

    private static void ratio(Map<String, Double> ns, String rotating, String fixed) {
        System.out.printf("%-40s %11.1fx%n", rotating, ns.get(rotating) / ns.get(fixed));
    }
}
