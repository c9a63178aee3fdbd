package physics;

import java.util.function.DoubleSupplier;

/**
 * A plain micro-benchmark, not a test: {@code gradle :physics-lib:benchmark} prints nanoseconds per call of the
 * main collision and reflection methods on fixed flipper-sized scenes. Numbers depend on the machine and load.
 */
public final class GeometryBenchmark {
    private static final int WARM_UP = 200_000;
    private static final int MEASURED = 1_000_000;
    private static double sink;

    private GeometryBenchmark() {
    }

    public static void main(String[] args) {
        LineSegment flipper = new LineSegment(0, 0, 2, 0);
        Circle ball = new Circle(1, 1.5, 0.25);
        Circle far = new Circle(15, 15, 0.25);
        Vect v = new Vect(0.3, -4);
        Circle bumper = new Circle(1, -1, 0.5);
        double w = Math.toRadians(1080);
        report("timeUntilWallCollision", () -> Geometry.timeUntilWallCollision(flipper, ball, v));
        report("timeUntilCircleCollision", () -> Geometry.timeUntilCircleCollision(bumper, ball, v));
        report("timeUntilBallBallCollision", () -> Geometry.timeUntilBallBallCollision(ball, v, bumper, Vect.ZERO));
        report("reflectWall", () -> Geometry.reflectWall(flipper, v, 0.95).x());
        report("reflectCircle", () -> Geometry.reflectCircle(bumper.getCenter(), ball.getCenter(), v, 0.95).x());
        report("reflectBalls", () -> Geometry.reflectBalls(ball.getCenter(), 1, v, bumper.getCenter(), 2,
                Vect.ZERO).v1.x());
        report("timeUntilRotatingWallCollision (hit)",
                () -> Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, w, ball, v));
        report("timeUntilRotatingWallCollision (out of reach)",
                () -> Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, w, far, v));
        report("timeUntilRotatingWallCollision (ball at rest)",
                () -> Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, w, ball, Vect.ZERO));
        report("timeUntilRotatingCircleCollision (hit)",
                () -> Geometry.timeUntilRotatingCircleCollision(new Circle(2, 0, 0.25), Vect.ZERO, w, ball, v));
        report("reflectRotatingWall", () -> Geometry.reflectRotatingWall(flipper, Vect.ZERO, w,
                new Circle(1, 0.25, 0.25), v, 0.95).y());
        System.out.println("(sink " + sink + ")");
    }

    private static void report(String name, DoubleSupplier call) {
        for (int i = 0; i < WARM_UP; i++) {
            sink += call.getAsDouble();
        }
        int calls = name.contains("Rotating") && name.contains("time") ? MEASURED / 20 : MEASURED;
        long start = System.nanoTime();
        for (int i = 0; i < calls; i++) {
            sink += call.getAsDouble();
        }
        System.out.printf("%-48s %10.1f ns/call%n", name, (System.nanoTime() - start) / (double) calls);
    }
}
