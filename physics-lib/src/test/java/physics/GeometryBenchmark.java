package physics;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.function.IntToDoubleFunction;

/**
 * A plain micro-benchmark, not a test: {@code gradle :physics-lib:benchmark} prints nanoseconds per call of every
 * public collision and reflection method of {@link Geometry}, then the ratio of each rotating method to its static
 * counterpart on the same scenes, and writes both as Markdown tables to the file its one argument names (the
 * build gives {@code docs/bench/physics-lib.md}), so that documents link to a run instead of retyping one. Numbers
 * depend on the machine and its load, which the page states.
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

    /** Each rotating method beside its static counterpart on the same scenes. */
    private static final List<List<String>> PAIRS = List.of(
            List.of("timeUntilRotatingWallCollision", "timeUntilWallCollision"),
            List.of("timeUntilRotatingCircleCollision", "timeUntilCircleCollision"),
            List.of("reflectRotatingWall (coefficient)", "reflectWall (coefficient)"),
            List.of("reflectRotatingCircle (coefficient)", "reflectCircle (coefficient)"));

    /** {@code [PAGE]}: also write the figures as Markdown to that file. */
    public static void main(String[] args) throws IOException {
        if (args.length > 1) {
            throw new IllegalArgumentException("usage: GeometryBenchmark [PAGE.md]");
        }
        String start = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm 'UTC'").format(Instant.now().atOffset(ZoneOffset.UTC));
        double loadAtStart = load();
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
        for (List<String> pair : PAIRS) {
            System.out.printf("%-40s %11.1fx%n", pair.get(0), ns.get(pair.get(0)) / ns.get(pair.get(1)));
        }
        System.out.println("(sink " + sink + ")");
        if (args.length == 1) {
            Path page = Path.of(args[0]);
            Files.createDirectories(page.toAbsolutePath().getParent());
            Files.writeString(page, page(ns, start, loadAtStart));
            System.out.println("wrote " + page.toAbsolutePath());
        }
    }

    /** The figures as Markdown: when and under what load, every method, then each rotating method against its static one. */
    private static String page(Map<String, Double> ns, String start, double loadAtStart) {
        StringBuilder md = new StringBuilder("# physics-lib: nanoseconds per call\n\n");
        md.append(String.format(Locale.ROOT, "Written by `gradle :physics-lib:benchmark` (do not edit: the next run rewrites "
                + "it). Run of %s, load average %.2f at the start and %.2f at the end on %d processors. Each method runs "
                + "over the same %d flipper-sized scenes (fixed seed); each figure is the fastest of %d rounds of the "
                + "thread's CPU time after a warm-up (`physics.GeometryBenchmark`).%n%n", start, loadAtStart, load(),
                Runtime.getRuntime().availableProcessors(), SCENES, ROUNDS));
        md.append("| method | ns per call |\n|---|---:|\n");
        ns.forEach((name, value) -> md.append(String.format(Locale.ROOT, "| %s | %.1f |%n", code(name), value)));
        md.append("\n| rotating method | ns per call | static method | ns per call | rotating / static |\n")
                .append("|---|---:|---|---:|---:|\n");
        for (List<String> pair : PAIRS) {
            double rotating = ns.get(pair.get(0));
            double fixed = ns.get(pair.get(1));
            md.append(String.format(Locale.ROOT, "| %s | %.1f | %s | %.1f | %.1fx |%n", code(pair.get(0)), rotating,
                    code(pair.get(1)), fixed, rotating / fixed));
        }
        return md.toString();
    }

    /** A method's name as code, its variant in words: {@code `reflectWall` (coefficient)}. */
    private static String code(String name) {
        if (name.startsWith("(")) {
            return name;
        }
        int space = name.indexOf(' ');
        return space < 0 ? "`" + name + "`" : "`" + name.substring(0, space) + "`" + name.substring(space);
    }

    private static double load() {
        return ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
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

}
