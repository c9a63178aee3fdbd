package physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.stream.LongStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The rotating methods against the brute-force oracle ({@link WorldGap}): over random flipper-like scenes the
 * method's contact is never later than the oracle's and, when reported, is a true contact (gap within 1e-9 L).
 */
class RotatingOracleTest {
    private static final double CONTACT = 1e-9;
    private static final double FORESIGHT = GeometryImpl.DEFAULT_FORESIGHT;

    static LongStream seeds() {
        return RandomScene.seeds(120);
    }

    /** Up to 20 rad/s either way (1080 deg/s is 18.8 rad/s), sometimes not turning at all. */
    static double angularVelocity(RandomScene r) {
        double magnitude = r.between(0, 1) < 0.1 ? 0 : r.between(0.5, 20);
        return r.coin() ? magnitude : -magnitude;
    }

    /** Sometimes at rest (pitfall 2), otherwise up to 30 L/s. */
    static Vect ballVelocity(RandomScene r) {
        return r.between(0, 1) < 0.2 ? Vect.ZERO : r.vector(0, 30);
    }

    /** A flipper-like segment turning about a pivot at or near one end, and a ball that starts clear of it. */
    private record WallScene(LineSegment segment, Vect pivot, double w, Circle ball, Vect velocity, WorldGap gap) {
        static WallScene random(RandomScene r) {
            Vect pivot = r.point(5);
            Vect p1 = r.coin() ? pivot : pivot.plus(r.vector(0, 0.5));
            LineSegment segment = new LineSegment(p1, p1.plus(r.vector(1, 2.5)));
            double w = angularVelocity(r);
            Vect velocity = ballVelocity(r);
            WorldGap gap;
            Circle ball;
            do { // a ball that starts clear of the segment
                ball = new Circle(pivot.plus(r.vector(0.3, 3.5)), r.between(0.1, 0.5));
                gap = WorldGap.wall(segment, pivot, w, ball, velocity);
            } while (gap.at(0) <= 0);
            return new WallScene(segment, pivot, w, ball, velocity, gap);
        }

        double face() {
            return Geometry.timeUntilRotatingWallCollision(segment, pivot, w, ball, velocity);
        }

        double end(Vect end) {
            return Geometry.timeUntilRotatingCircleCollision(new Circle(end, 0), pivot, w, ball, velocity);
        }
    }

    /** The face and the zero-radius circles at the ends together find every contact of the closed segment. */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void rotatingWallContactIsNeverLaterThanTheOracleAndIsExact(long seed) {
        WallScene scene = WallScene.random(new RandomScene(seed));
        double t = Math.min(scene.face(), Math.min(scene.end(scene.segment.p1()), scene.end(scene.segment.p2())));
        assertAgreesWithOracle(seed, scene.gap, t);
    }

    /** The face alone: its contacts are the oracle's face contacts, never later, and lie on the face. */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void rotatingWallFindsTheFaceContactsOfTheOracleAndOnlyThose(long seed) {
        WallScene scene = WallScene.random(new RandomScene(seed));
        double t = scene.face();
        double oracle = scene.gap.firstFaceContact(FORESIGHT);
        if (oracle < Double.POSITIVE_INFINITY) {
            assertThat(t).as("seed %d: oracle face contact at %s must not be missed or reported late", seed, oracle)
                    .isLessThanOrEqualTo(oracle + CONTACT);
        }
        if (t < Double.POSITIVE_INFINITY) {
            assertThat(t).as("seed %d: inside the foresight window", seed).isBetween(0.0, FORESIGHT);
            assertThat(Math.abs(scene.gap.faceGap(t))).as("seed %d: face gap at the reported time %s", seed, t)
                    .isLessThanOrEqualTo(CONTACT);
            assertThat(scene.gap.footBeyond(t)).as("seed %d: foot beyond the ends at %s", seed, t)
                    .isLessThanOrEqualTo(CONTACT);
        }
    }

    static LongStream manySeeds() {
        return RandomScene.seeds(1000);
    }

    /**
     * Time, then reflect, as a program written for the API does: every contact the face method reports is one that
     * reflectRotatingWall reflects, also when it lies within rounding of an end. Half the balls start near an end,
     * where such contacts are. The reflected velocity leaves the face, relative to its moving surface.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("manySeeds")
    void everyReportedFaceContactReflects(long seed) {
        RandomScene r = new RandomScene(seed);
        WallScene scene = WallScene.random(r);
        Circle ball = scene.ball;
        if (r.coin()) { // near an end instead
            Vect end = r.coin() ? scene.segment.p1() : scene.segment.p2();
            do {
                ball = new Circle(end.plus(r.vector(ball.getRadius(), ball.getRadius() + 0.5)), ball.getRadius());
            } while (WorldGap.wall(scene.segment, scene.pivot, scene.w, ball, scene.velocity).at(0) <= 0);
        }
        double t = Geometry.timeUntilRotatingWallCollision(scene.segment, scene.pivot, scene.w, ball, scene.velocity);
        if (t == Double.POSITIVE_INFINITY) {
            return;
        }
        LineSegment then = Geometry.rotateAround(scene.segment, scene.pivot, new Angle(scene.w * t));
        Circle ballThen = new Circle(ball.getCenter().plus(scene.velocity.times(t)), ball.getRadius());
        Vect out = Geometry.reflectRotatingWall(then, scene.pivot, scene.w, ballThen, scene.velocity);
        Vect foot = Geometry.perpendicularPointWholeLine(then, ballThen.getCenter());
        Vect arm = foot.minus(scene.pivot);
        Vect surface = new Vect(-arm.y(), arm.x()).times(scene.w);
        Vect away = ballThen.getCenter().minus(foot);
        assertThat(out.minus(surface).dot(away)).as("seed %d: leaves the face at %s", seed, t)
                .isGreaterThanOrEqualTo(-1e-12 * (1 + scene.velocity.length() + surface.length()));
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void rotatingCircleContactIsNeverLaterThanTheOracleAndIsExact(long seed) {
        RandomScene r = new RandomScene(seed);
        Vect pivot = r.point(5);
        Circle circle = new Circle(pivot.plus(r.vector(0, 2.5)), r.coin() ? 0 : r.between(0.05, 0.5));
        double w = angularVelocity(r);
        Vect velocity = ballVelocity(r);
        WorldGap gap;
        Circle ball;
        do { // a ball that starts clear of the circle
            ball = new Circle(pivot.plus(r.vector(0.3, 3.5)), r.between(0.1, 0.5));
            gap = WorldGap.circle(circle, pivot, w, ball, velocity);
        } while (gap.at(0) <= 0);

        double t = Geometry.timeUntilRotatingCircleCollision(circle, pivot, w, ball, velocity);
        assertAgreesWithOracle(seed, gap, t);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void rotatingReflectionsKeepTheRelativeSpeedAndUndoThemselves(long seed) {
        RandomScene r = new RandomScene(seed);
        Vect pivot = r.point(5);
        LineSegment segment = new LineSegment(pivot, pivot.plus(r.vector(1, 2.5)));
        double w = angularVelocity(r);
        Vect dir = segment.p2().minus(segment.p1()).unitSize();
        Vect contact = segment.p1().plus(segment.p2().minus(segment.p1()).times(r.between(0.05, 0.95)));
        double radius = r.between(0.1, 0.5);
        Circle ball = new Circle(contact.plus(new Vect(-dir.y(), dir.x()).times(r.coin() ? radius : -radius)),
                radius);
        Vect v = r.vector(0, 30);
        Vect arm = contact.minus(pivot);
        Vect surface = new Vect(-arm.y(), arm.x()).times(w);
        Vect once = Geometry.reflectRotatingWall(segment, pivot, w, ball, v);
        assertThat(once.minus(surface).length()).as("seed %d: relative speed", seed)
                .isCloseTo(v.minus(surface).length(), within(1e-12 * (1 + v.length() + surface.length())));
        Vect twice = Geometry.reflectRotatingWall(segment, pivot, w, ball, once);
        assertThat(twice.minus(v).length()).as("seed %d: reflecting twice", seed).isLessThan(1e-12 * (1 + v.length()
                + surface.length()));
        // The tangential part relative to the surface is untouched, whatever the coefficient.
        double coeff = r.between(0, 1);
        Vect damped = Geometry.reflectRotatingWall(segment, pivot, w, ball, v, coeff);
        assertThat(damped.minus(surface).dot(dir)).as("seed %d: tangential part", seed)
                .isCloseTo(v.minus(surface).dot(dir), within(1e-12 * (1 + v.length() + surface.length())));

        Circle end = new Circle(segment.p2(), r.between(0, 0.3));
        Vect outward = r.vector(1, 1);
        Circle touching = new Circle(end.getCenter().plus(outward.times(end.getRadius() + radius)), radius);
        Vect endArm = end.getCenter().plus(outward.times(end.getRadius())).minus(pivot);
        Vect endSurface = new Vect(-endArm.y(), endArm.x()).times(w);
        Vect offCircle = Geometry.reflectRotatingCircle(end, pivot, w, touching, v);
        assertThat(offCircle.minus(endSurface).length()).as("seed %d: relative speed off the circle", seed)
                .isCloseTo(v.minus(endSurface).length(), within(1e-12 * (1 + v.length() + endSurface.length())));
        Vect back = Geometry.reflectRotatingCircle(end, pivot, w, touching, offCircle);
        assertThat(back.minus(v).length()).as("seed %d: circle twice", seed).isLessThan(1e-12 * (1 + v.length()
                + endSurface.length()));
    }

    /**
     * A game asks about what is left of a tick, a sixtieth of a second or less, and most balls near a swinging flipper
     * cannot reach it in that time: the search refuses those at once, where the gap at the start exceeds what its rate
     * bound, |v| + |w| |u|, closes over the window. The bound must never refuse a ball the swing does meet: over short
     * windows, balls near the face and still balls among them (only the swing can bring those in), the face's
     * contacts and the ends' are never later than the oracle's. Both kinds of scene occur (79 contacts and 327 balls
     * the bound refuses, of 600).
     */
    @Test
    void overWhatIsLeftOfATickNoContactIsRefused() {
        int contacts = 0;
        int refusable = 0;
        for (long seed : RandomScene.seeds(600).toArray()) {
            RandomScene r = new RandomScene(seed);
            double foresight = r.between(1e-4, 1.0 / 60);
            GeometryImpl geometry = new GeometryImpl(foresight, GeometryImpl.DEFAULT_SEARCH_SLICES);
            Vect pivot = r.point(5);
            LineSegment segment = new LineSegment(pivot, pivot.plus(r.vector(1, 2.5)));
            double w = (r.coin() ? 1 : -1) * r.between(0.5, 20);   // turning: at rest the window does not apply
            Vect velocity = ballVelocity(r);
            double radius = r.between(0.1, 0.5);
            Vect near = segment.p1().plus(segment.p2().minus(segment.p1()).times(r.between(-0.2, 1.2)));
            Circle ball;
            WorldGap gap;
            do { // within 0.6 L of the face or its line beyond the ends, clear of it
                ball = new Circle(near.plus(r.vector(radius, radius + 0.6)), radius);
                gap = WorldGap.wall(segment, pivot, w, ball, velocity);
            } while (gap.at(0) <= 0);
            double face = geometry.timeUntilRotatingWallCollision(segment, pivot, w, ball, velocity);
            double ends = Math.min(
                    geometry.timeUntilRotatingCircleCollision(new Circle(segment.p1(), 0), pivot, w, ball, velocity),
                    geometry.timeUntilRotatingCircleCollision(new Circle(segment.p2(), 0), pivot, w, ball, velocity));
            assertAgreesWithOracle(seed, gap, Math.min(face, ends), foresight);
            double fromPivot = ball.getCenter().minus(pivot).length() + velocity.length() * foresight;
            if (gap.firstContact(foresight) < Double.POSITIVE_INFINITY) {
                contacts++;
            } else if (gap.at(0) > (velocity.length() + Math.abs(w) * fromPivot) * foresight) {
                refusable++;
            }
        }
        assertThat(contacts).as("scenes with a contact in the window").isGreaterThan(50);
        assertThat(refusable).as("scenes whose ball the bound refuses").isGreaterThan(50);
    }

    static void assertAgreesWithOracle(long seed, WorldGap gap, double t) {
        assertAgreesWithOracle(seed, gap, t, FORESIGHT);
    }

    /** As above, over a foresight of {@code foresight} seconds. */
    static void assertAgreesWithOracle(long seed, WorldGap gap, double t, double foresight) {
        double oracle = gap.firstContact(foresight);
        if (oracle < Double.POSITIVE_INFINITY) {
            assertThat(t).as("seed %d: oracle contact at %s must not be missed or reported late", seed, oracle)
                    .isLessThanOrEqualTo(oracle + CONTACT);
        }
        if (t < Double.POSITIVE_INFINITY) {
            assertThat(t).as("seed %d: inside the foresight window", seed).isBetween(0.0, foresight);
            assertThat(Math.abs(gap.at(t))).as("seed %d: gap at the reported time %s", seed, t)
                    .isLessThanOrEqualTo(CONTACT);
        }
    }
}
