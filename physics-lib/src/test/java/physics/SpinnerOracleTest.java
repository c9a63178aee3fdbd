package physics;

import static physics.RotatingOracleTest.assertAgreesWithOracle;

import java.util.stream.LongStream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The rotating methods against the brute-force oracle ({@link WorldGap}) for a spinner's bar, as
 * {@link RotatingOracleTest} does for flipper-like bars: the bar's pivot is its centre, its side segments lie 0.25
 * to either side of the pivot and its round ends (radius 0.25) 0.75 from it, and it turns a full circle within the
 * foresight, at a quarter turn to three turns a second either way, with balls at rest or up to 6 L/s (most of them met within the turn). Over that whole turn the method's contact is
 * never later than the oracle's and, when reported, is a true contact (gap within 1e-9 L).
 */
class SpinnerOracleTest {
    private static final double ARM = 0.75;
    private static final double RADIUS = 0.25;

    static LongStream seeds() {
        return RandomScene.seeds(120);
    }

    /** A spinner's scene: its pivot, angle, speed, and a ball that starts clear of the part asked about. */
    private record Scene(Vect pivot, Vect along, double w, double turn, Vect velocity, RandomScene random) {
        static Scene random(RandomScene r) {
            Vect pivot = r.point(5);
            double turns = r.between(0.25, 3);
            double w = 2 * Math.PI * (r.coin() ? turns : -turns);
            Vect velocity = r.between(0, 1) < 0.3 ? Vect.ZERO : r.vector(0, 6);
            return new Scene(pivot, r.vector(1, 1), w, 1 / turns, velocity, r);
        }

        /** A side segment: parallel to the bar, 0.25 from the pivot, from one end's centre to the other's. */
        LineSegment side() {
            Vect across = new Vect(-along.y(), along.x()).times(random.coin() ? RADIUS : -RADIUS);
            return new LineSegment(pivot.minus(along.times(ARM)).plus(across), pivot.plus(along.times(ARM)).plus(across));
        }

        /** A round end: 0.75 from the pivot, radius 0.25. */
        Circle end() {
            return new Circle(pivot.plus(along.times(random.coin() ? ARM : -ARM)), RADIUS);
        }

        /** A ball up to 1.8 L from the pivot, mostly within reach of the turning bar (1 L and its radius). */
        Circle ball() {
            return new Circle(pivot.plus(random.vector(0.3, 1.8)), random.between(0.1, 0.5));
        }

        /** The foresight of one full turn and the default slices, so that the search covers the whole circle. */
        GeometryImpl geometry() {
            return new GeometryImpl(turn, GeometryImpl.DEFAULT_SEARCH_SLICES);
        }
    }

    /** A side segment (its face and the zero-radius circles at its ends) over a whole turn. */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void aSideOfTheBarTurningAFullCircleMeetsTheBallNeverLaterThanTheOracle(long seed) {
        Scene scene = Scene.random(new RandomScene(seed));
        LineSegment side = scene.side();
        Circle ball;
        WorldGap gap;
        do {
            ball = scene.ball();
            gap = WorldGap.wall(side, scene.pivot(), scene.w(), ball, scene.velocity());
        } while (gap.at(0) <= 0);
        GeometryImpl geometry = scene.geometry();
        double t = Math.min(geometry.timeUntilRotatingWallCollision(side, scene.pivot(), scene.w(), ball,
                        scene.velocity()),
                Math.min(end(geometry, side.p1(), scene, ball), end(geometry, side.p2(), scene, ball)));
        assertAgreesWithOracle(seed, gap, t, scene.turn());
    }

    /** A round end over a whole turn. */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void anEndOfTheBarTurningAFullCircleMeetsTheBallNeverLaterThanTheOracle(long seed) {
        Scene scene = Scene.random(new RandomScene(seed));
        Circle end = scene.end();
        Circle ball;
        WorldGap gap;
        do {
            ball = scene.ball();
            gap = WorldGap.circle(end, scene.pivot(), scene.w(), ball, scene.velocity());
        } while (gap.at(0) <= 0);
        double t = scene.geometry().timeUntilRotatingCircleCollision(end, scene.pivot(), scene.w(), ball,
                scene.velocity());
        assertAgreesWithOracle(seed, gap, t, scene.turn());
    }

    private static double end(GeometryImpl geometry, Vect corner, Scene scene, Circle ball) {
        return geometry.timeUntilRotatingCircleCollision(new Circle(corner, 0), scene.pivot(), scene.w(), ball,
                scene.velocity());
    }
}
