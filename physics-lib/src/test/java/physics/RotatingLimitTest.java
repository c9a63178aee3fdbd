package physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.stream.LongStream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every rotating method is its static counterpart in the limits: at angular velocity 0 and as it goes to 0, and for
 * a pivot far away, where a rotation becomes a translation at the surface velocity V = w x (surface - pivot).
 * <p>
 * Random well-posed scenes from fixed seeds: the ball starts clear of the obstacle; it meets it with a normal
 * closing speed of at least {@value #MIN_CLOSING} L/s, at least {@value #END_MARGIN} L inside the face's ends,
 * or passes beyond an end or the circle by at least that much, or moves away, or rests. Hit or miss must agree.
 * <p>
 * Tolerances from the mathematics. Turning at |w| for t &le; 1 s moves an obstacle point at distance &rho; from
 * the pivot by at most |w| &rho; t; at |w| = 1e-12 and &rho; &lt; 20 L that is 2e-11 L, which at the closing
 * speed moves the contact by under 1e-10 s; the rotating search stops within 1e-10 L, under 2e-10 s. So the times
 * agree within 1e-9 s. For a pivot at distance D, rotating at w = V/D about it differs from translating at V by
 * at most (|V|&sup2; t&sup2;/2 + |V| t &rho;)/D in position, where &rho; is the distance from the point whose velocity
 * is V: the times then agree within that over the closing speed.
 */
class RotatingLimitTest {
    private static final double INF = Double.POSITIVE_INFINITY;
    private static final double FORESIGHT = 1;
    private static final double MIN_CLOSING = 0.5;
    private static final double END_MARGIN = 0.05;
    private static final double TIME = 1e-9;
    private static final double[] VANISHING_SPIN = {0, 1e-12, -1e-12};
    private static final double[] FAR = {1e3, 1e4, 1e5, 1e6};
    /** Speed of the surface for the far-pivot limit, L/s. */
    private static final double SURFACE_SPEED = 3;

    static LongStream seeds() {
        return RandomScene.seeds(400);
    }

    /** A segment, a ball and its velocity relative to the segment, built so that the static answer is robust. */
    private record WallCase(LineSegment segment, Circle ball, Vect relative) {
        static WallCase random(RandomScene r) {
            Vect p1 = r.point(5);
            LineSegment segment = new LineSegment(p1, p1.plus(r.vector(1, 3)));
            Vect along = segment.p2().minus(p1).unitSize();
            double side = r.coin() ? 1 : -1;
            Vect normal = new Vect(-along.y(), along.x()).times(side);
            double radius = r.between(0.1, 0.5);
            double kind = r.between(0, 1);
            // Where the centre is when it is at the contact distance from the line, and the velocity.
            double foot = kind < 0.5 ? r.between(END_MARGIN, segment.length() - END_MARGIN)
                    : r.coin() ? r.between(-1.5, -END_MARGIN) : segment.length() + r.between(END_MARGIN, 1.5);
            Vect atLine = p1.plus(along.times(foot)).plus(normal.times(radius));
            Vect velocity = normal.times(-r.between(MIN_CLOSING, 10)).plus(along.times(r.between(-10, 10)));
            double time = r.between(0.05, 0.9);
            if (kind > 0.9) {
                return new WallCase(segment, new Circle(atLine.plus(normal.times(r.between(END_MARGIN, 2))), radius),
                        r.coin() ? Vect.ZERO : velocity.neg());
            }
            return new WallCase(segment, new Circle(atLine.minus(velocity.times(time)), radius), velocity);
        }
    }

    /** A circle, a ball and its velocity relative to the circle: a hit, a miss by at least END_MARGIN, or away. */
    private record CircleCase(Circle circle, Circle ball, Vect relative) {
        static CircleCase random(RandomScene r) {
            Circle circle = new Circle(r.point(5), r.coin() ? 0 : r.between(0.05, 0.5));
            double radius = r.between(0.1, 0.5);
            double sum = circle.getRadius() + radius;
            Vect direction = r.vector(1, 1);
            Vect across = new Vect(-direction.y(), direction.x());
            double kind = r.between(0, 1);
            // Aimed at the offset b from the centre across the line of motion: a hit for |b| < sum, here at most
            // 0.8 sum, so that the normal closing speed is at least 0.6 times the speed.
            double aim = kind < 0.5 ? r.between(-0.8, 0.8) * sum
                    : (r.coin() ? 1 : -1) * (sum + r.between(END_MARGIN, 1));
            double speed = r.between(3, 10);
            // Before any contact, which comes within (sum + 0.5 speed) / speed < 0.9 s; or moving away.
            Vect start = circle.getCenter().plus(across.times(aim))
                    .minus(direction.times(sum + r.between(0.05, 0.5) * speed));
            Vect velocity = direction.times(speed);
            if (kind > 0.9) {
                velocity = r.coin() ? Vect.ZERO : velocity.neg();
            }
            return new CircleCase(circle, new Circle(start, radius), velocity);
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void rotatingWallIsTheStaticWallAsTheSpinVanishes(long seed) {
        RandomScene r = new RandomScene(seed);
        WallCase c = WallCase.random(r);
        Vect pivot = r.point(8);
        double expected = withinForesight(Geometry.timeUntilWallCollision(c.segment, c.ball, c.relative));
        for (double w : VANISHING_SPIN) {
            double t = Geometry.timeUntilRotatingWallCollision(c.segment, pivot, w, c.ball, c.relative);
            assertSameTime(seed, "w = " + w, t, expected, TIME);
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void rotatingCircleIsTheStaticCircleAsTheSpinVanishes(long seed) {
        RandomScene r = new RandomScene(seed);
        CircleCase c = CircleCase.random(r);
        Vect pivot = r.point(8);
        double expected = withinForesight(Geometry.timeUntilCircleCollision(c.circle, c.ball, c.relative));
        for (double w : VANISHING_SPIN) {
            double t = Geometry.timeUntilRotatingCircleCollision(c.circle, pivot, w, c.ball, c.relative);
            assertSameTime(seed, "w = " + w, t, expected, TIME);
        }
    }

    /** About a far pivot the segment translates at V: the static wall met at the velocity relative to it. */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void rotatingWallAboutAFarPivotIsTheStaticWallMetAtTheRelativeVelocity(long seed) {
        RandomScene r = new RandomScene(seed);
        WallCase c = WallCase.random(r);
        Vect middle = c.segment.p1().plus(c.segment.p2()).times(0.5);
        Vect out = r.vector(1, 1);
        double expected = withinForesight(Geometry.timeUntilWallCollision(c.segment, c.ball, c.relative));
        double rho = c.segment.length() / 2;
        for (double distance : FAR) {
            Vect pivot = middle.plus(out.times(distance));
            double w = (r.coin() ? 1 : -1) * SURFACE_SPEED / distance;
            Vect surface = surfaceVelocity(middle, pivot, w);
            double t = Geometry.timeUntilRotatingWallCollision(c.segment, pivot, w, c.ball, c.relative.plus(surface));
            assertSameTime(seed, "D = " + distance, t, expected, farPivotTime(rho, distance));
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void rotatingCircleAboutAFarPivotIsTheStaticCircleMetAtTheRelativeVelocity(long seed) {
        RandomScene r = new RandomScene(seed);
        CircleCase c = CircleCase.random(r);
        Vect out = r.vector(1, 1);
        double expected = withinForesight(Geometry.timeUntilCircleCollision(c.circle, c.ball, c.relative));
        for (double distance : FAR) {
            Vect pivot = c.circle.getCenter().plus(out.times(distance));
            double w = (r.coin() ? 1 : -1) * SURFACE_SPEED / distance;
            Vect surface = surfaceVelocity(c.circle.getCenter(), pivot, w);
            double t = Geometry.timeUntilRotatingCircleCollision(c.circle, pivot, w, c.ball,
                    c.relative.plus(surface));
            assertSameTime(seed, "D = " + distance, t, expected, farPivotTime(c.circle.getRadius(), distance));
        }
    }

    /**
     * The rotating reflections at w = 0 are the static ones; about a far pivot they are the static ones applied to
     * the velocity relative to the surface, which is then added back. Off a ball touching the face or the circle.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void rotatingReflectionsAreTheStaticOnesInTheLimits(long seed) {
        RandomScene r = new RandomScene(seed);
        Vect p1 = r.point(5);
        LineSegment segment = new LineSegment(p1, p1.plus(r.vector(1, 3)));
        Vect along = segment.p2().minus(p1).unitSize();
        double radius = r.between(0.1, 0.5);
        Vect foot = p1.plus(along.times(r.between(0, segment.length())));
        Circle onFace = new Circle(foot.plus(new Vect(-along.y(), along.x()).times(r.coin() ? radius : -radius)),
                radius);
        Circle circle = new Circle(r.point(5), r.between(0, 0.5));
        Circle onCircle = new Circle(circle.getCenter().plus(r.vector(1, 1).times(circle.getRadius() + radius)),
                radius);
        Vect v = r.vector(0, 20);
        double coeff = r.between(0, 1);
        Vect pivot = r.point(8);
        assertClose(seed, Geometry.reflectRotatingWall(segment, pivot, 0, onFace, v), Geometry.reflectWall(segment, v),
                1e-12);
        assertClose(seed, Geometry.reflectRotatingWall(segment, pivot, 0, onFace, v, coeff),
                Geometry.reflectWall(segment, v, coeff), 1e-12);
        assertClose(seed, Geometry.reflectRotatingCircle(circle, pivot, 0, onCircle, v),
                Geometry.reflectCircle(circle.getCenter(), onCircle.getCenter(), v), 1e-12);
        assertClose(seed, Geometry.reflectRotatingCircle(circle, pivot, 0, onCircle, v, coeff),
                Geometry.reflectCircle(circle.getCenter(), onCircle.getCenter(), v, coeff), 1e-12);

        Vect out = r.vector(1, 1);
        for (double distance : FAR) {
            double w = (r.coin() ? 1 : -1) * SURFACE_SPEED / distance;
            // The surface velocity at the foot and at the circle's point of contact differ from V at the
            // reference point by |w| times their distance from it, at most (1 + coeff) times that in the result.
            Vect facePivot = foot.plus(out.times(distance));
            Vect faceSurface = surfaceVelocity(foot, facePivot, w);
            assertClose(seed, Geometry.reflectRotatingWall(segment, facePivot, w, onFace, v, coeff),
                    Geometry.reflectWall(segment, v.minus(faceSurface), coeff).plus(faceSurface), 1e-9);
            Vect circlePivot = circle.getCenter().plus(out.times(distance));
            Vect circleSurface = surfaceVelocity(circle.getCenter(), circlePivot, w);
            assertClose(seed, Geometry.reflectRotatingCircle(circle, circlePivot, w, onCircle, v, coeff),
                    Geometry.reflectCircle(circle.getCenter(), onCircle.getCenter(), v.minus(circleSurface), coeff)
                            .plus(circleSurface), 2 * SURFACE_SPEED * circle.getRadius() / distance + 1e-9);
        }
    }

    /** The velocity of the point turning at w about the pivot: w J (point - pivot), J (x, y) = (-y, x). */
    private static Vect surfaceVelocity(Vect point, Vect pivot, double w) {
        Vect arm = point.minus(pivot);
        return new Vect(-arm.y(), arm.x()).times(w);
    }

    /** The bound of the class comment over the foresight, divided by the least closing speed, plus the search's. */
    private static double farPivotTime(double rho, double distance) {
        double shift = (SURFACE_SPEED * SURFACE_SPEED * FORESIGHT * FORESIGHT / 2 + SURFACE_SPEED * FORESIGHT * rho)
                / distance;
        return shift / MIN_CLOSING + TIME;
    }

    private static double withinForesight(double time) {
        return time <= FORESIGHT ? time : INF;
    }

    private static void assertSameTime(long seed, String limit, double actual, double expected, double tolerance) {
        if (expected == INF) {
            assertThat(actual).as("seed %d, %s: a miss, as the static method says", seed, limit).isEqualTo(INF);
        } else {
            assertThat(actual).as("seed %d, %s: the static contact", seed, limit)
                    .isCloseTo(expected, within(tolerance));
        }
    }

    private static void assertClose(long seed, Vect actual, Vect expected, double tolerance) {
        assertThat(actual.minus(expected).length()).as("seed %d: %s vs %s", seed, actual, expected)
                .isLessThanOrEqualTo(tolerance * Math.max(1, expected.length()));
    }
}
