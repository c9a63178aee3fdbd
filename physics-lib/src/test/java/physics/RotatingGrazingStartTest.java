package physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.stream.LongStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Rotating contacts that begin touching with zero closing speed (issue 20, item 2). When the obstacle then closes
 * on the ball, that is a collision at once: before the ball is {@value #CONTACT} L deep by the oracle, within that
 * of touching, and with a closing speed for a reflection to act on. When the obstacle then leaves it, it is no
 * collision at time 0. The brute-force oracle ({@link WorldGap#start}) decides which, from the world-frame geometry.
 * <p>
 * The flipper case: a ball lying against the round pivot end of a flipper, at the point where that end meets a
 * side face. Turning toward the ball, the side takes it over from the end with zero closing speed and then
 * sweeps into it; the face method must report that at once, never late and never "never".
 */
class RotatingGrazingStartTest {
    private static final double CONTACT = 1e-9;

    static LongStream seeds() {
        return RandomScene.seeds(300);
    }

    /** A scene that touches at time 0 with zero closing speed, the oracle's verdict on it, and the method's time. */
    private record Grazing(WorldGap gap, WorldGap.Start start, double time) {
    }

    /**
     * The end-to-side hand-over: a flipper-like side face at distance endRadius from the pivot (the side of a
     * flipper whose pivot end is a circle of that radius), and a ball touching both that end circle and the face's
     * corner, at rest or moving along the face (its closing speed relative to the surface there is zero).
     */
    private static Grazing handOver(RandomScene r) {
        Vect pivot = r.point(5);
        Vect along = r.vector(1, 1);
        Vect normal = new Vect(-along.y(), along.x()).times(r.coin() ? 1 : -1);
        double endRadius = r.coin() ? 0.25 : r.between(0, 0.5);
        Vect corner = pivot.plus(normal.times(endRadius));
        LineSegment face = r.coin() ? new LineSegment(corner, corner.plus(along.times(r.between(1, 2.5))))
                : new LineSegment(corner.plus(along.times(r.between(1, 2.5))), corner);
        double radius = r.between(0.1, 0.5);
        Circle ball = new Circle(corner.plus(normal.times(radius)), radius);
        Vect velocity = r.coin() ? Vect.ZERO : along.times(r.between(-5, 5));
        double w = turning(r);
        WorldGap gap = WorldGap.wall(face, pivot, w, ball, velocity);
        return new Grazing(gap, gap.start(), Geometry.timeUntilRotatingWallCollision(face, pivot, w, ball, velocity));
    }

    /** A ball touching a turning face inside its ends, its velocity relative to the surface there along the face. */
    private static Grazing midFace(RandomScene r) {
        Vect pivot = r.point(5);
        Vect p1 = pivot.plus(r.vector(0, 1));
        LineSegment face = new LineSegment(p1, p1.plus(r.vector(1, 2.5)));
        Vect along = face.p2().minus(face.p1()).unitSize();
        Vect normal = new Vect(-along.y(), along.x()).times(r.coin() ? 1 : -1);
        Vect foot = face.p1().plus(face.p2().minus(face.p1()).times(r.between(0.05, 0.95)));
        double radius = r.between(0.1, 0.5);
        Circle ball = new Circle(foot.plus(normal.times(radius)), radius);
        double w = turning(r);
        Vect surface = surfaceVelocity(pivot, w, foot);
        Vect velocity = normal.times(surface.dot(normal)).plus(along.times(r.between(-30, 30)));
        WorldGap gap = WorldGap.wall(face, pivot, w, ball, velocity);
        return new Grazing(gap, gap.start(), Geometry.timeUntilRotatingWallCollision(face, pivot, w, ball, velocity));
    }

    /**
     * A ball touching a turning circle, its velocity relative to the circle's surface there tangential. In the
     * circle's frame the ball's centre then moves along the circle of radius D (the sum of the radii) at a relative
     * speed m; it closes when its path curves in more than that circle does, which happens for m between the
     * roots of m^2 / D + 2 w m + w^2 s (s: the centre's distance from the pivot along the normal). The speed is
     * drawn around those roots, so that about as many scenes close as leave where closing is possible at all.
     */
    private static Grazing circle(RandomScene r) {
        Vect pivot = r.point(5);
        Circle circle = new Circle(pivot.plus(r.vector(0, 2.5)), r.coin() ? 0 : r.between(0.05, 0.5));
        Vect normal = r.vector(1, 1);
        Vect tangent = new Vect(-normal.y(), normal.x());
        double radius = r.between(0.1, 0.5);
        Circle ball = new Circle(circle.getCenter().plus(normal.times(circle.getRadius() + radius)), radius);
        double w = turning(r);
        double reach = circle.getRadius() + radius;
        double along = ball.getCenter().minus(pivot).dot(normal);
        double relativeSpeed = -w * reach * (1 + r.between(-2, 2) * Math.sqrt(Math.max(0, 1 - along / reach)));
        // The centre's velocity in the circle's frame is v - w J (c - pivot); its normal part is zero.
        Vect frame = surfaceVelocity(pivot, w, ball.getCenter());
        Vect velocity = normal.times(frame.dot(normal)).plus(tangent.times(frame.dot(tangent) + relativeSpeed));
        WorldGap gap = WorldGap.circle(circle, pivot, w, ball, velocity);
        return new Grazing(gap, gap.start(), Geometry.timeUntilRotatingCircleCollision(circle, pivot, w, ball,
                velocity));
    }

    /**
     * Up to 20 rad/s either way, never 0: a ball sliding along a still surface at zero normal speed neither closes
     * nor leaves, and only rounding would decide it.
     */
    private static double turning(RandomScene r) {
        double magnitude = r.between(0.5, 20);
        return r.coin() ? magnitude : -magnitude;
    }

    private static Vect surfaceVelocity(Vect pivot, double w, Vect point) {
        Vect arm = point.minus(pivot);
        return new Vect(-arm.y(), arm.x()).times(w);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void theSideTakingABallOverFromThePivotEndIsACollisionAtOnce(long seed) {
        assertMeaning(seed, handOver(new RandomScene(seed)), true);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void aFaceThatStartsTouchingAtZeroClosingSpeedCollidesAtOnceIfItThenCloses(long seed) {
        assertMeaning(seed, midFace(new RandomScene(seed)), true);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void aCircleThatStartsTouchingAtZeroClosingSpeedCollidesAtOnceIfItThenCloses(long seed) {
        assertMeaning(seed, circle(new RandomScene(seed)), false);
    }

    /** Both verdicts occur often among the scenes of each kind, so that each test above checks both meanings. */
    @Test
    void bothVerdictsOccurOftenAmongTheScenesOfEachKind() {
        int[][] counts = new int[3][WorldGap.Start.values().length];
        seeds().forEach(seed -> {
            counts[0][handOver(new RandomScene(seed)).start.ordinal()]++;
            counts[1][midFace(new RandomScene(seed)).start.ordinal()]++;
            counts[2][circle(new RandomScene(seed)).start.ordinal()]++;
        });
        for (int[] kind : counts) {
            assertThat(kind[WorldGap.Start.CLOSING.ordinal()]).as("closing scenes").isGreaterThan(50);
            assertThat(kind[WorldGap.Start.OPENING.ordinal()]).as("opening scenes").isGreaterThan(50);
        }
    }

    /**
     * The repro of issue 20 in closed form: a ball at rest against the round end (radius 0.25) of a flipper
     * turning at 1080 degrees/s, its centre 0.5 L from the pivot and at angle phi past the side face's normal.
     * The side takes it over when the flipper has turned by phi, at phi / w, and then goes into it: a turn of a
     * further alpha leaves the centre 0.5 cos(alpha) from the side's line, 0.5 (1 - cos alpha) deep. So the
     * contact lies between phi / w and the moment it is CONTACT deep, (phi + acos(1 - CONTACT / 0.5)) / w.
     */
    @Test
    void aBallLyingAgainstThePivotEndIsMetByTheSideWhenTheFlipperHasTurnedByItsAngle() {
        Vect pivot = new Vect(18.25, 19.75);
        double w = -Math.toRadians(1080);
        LineSegment side = new LineSegment(18.25, 19.5, 19.75, 19.5);
        double late = Math.acos(1 - CONTACT / 0.5) / -w;
        for (double phi : new double[] {0.01, 0.1, 0.3682, 1.0}) {
            Circle ball = new Circle(pivot.plus(new Vect(-Math.sin(phi), -Math.cos(phi)).times(0.5)), 0.25);
            double t = Geometry.timeUntilRotatingWallCollision(side, pivot, w, ball, Vect.ZERO);
            assertThat(t).as("phi %s", phi).isBetween(phi / -w - 1e-12, phi / -w + late);
            LineSegment then = Geometry.rotateAround(side, pivot, new Angle(w * phi / -w));
            double again = Geometry.timeUntilRotatingWallCollision(then, pivot, w, ball, Vect.ZERO);
            assertThat(again).as("phi %s: asked at the hand-over, the side closes at once", phi)
                    .isBetween(0.0, late);
            assertThat(WorldGap.wall(then, pivot, w, ball, Vect.ZERO).closingSpeed(again))
                    .as("phi %s: closing at %s", phi, again).isPositive();
        }
    }

    /**
     * Closing: at once, before the ball is CONTACT deep, within CONTACT of touching (on the face for a wall) and
     * closing. Opening: not time 0, and any later contact is a true one (on the face for a wall) and not later
     * than the oracle's first.
     */
    private static void assertMeaning(long seed, Grazing scene, boolean wall) {
        if (scene.start == WorldGap.Start.CLOSING) {
            assertThat(scene.time).as("seed %d: touching, then closing: before the ball is %s L deep", seed, CONTACT)
                    .isLessThanOrEqualTo(scene.gap.firstDeeperThan(CONTACT, WorldGap.START_HORIZON));
            double gap = wall ? scene.gap.faceGap(scene.time) : scene.gap.at(scene.time);
            assertThat(Math.abs(gap)).as("seed %d: gap at the reported time %s", seed, scene.time)
                    .isLessThanOrEqualTo(CONTACT);
            if (wall) {
                assertThat(scene.gap.footBeyond(scene.time)).as("seed %d: foot on the segment", seed).isZero();
            }
            assertThat(scene.gap.closingSpeed(scene.time)).as("seed %d: closing at %s", seed, scene.time)
                    .isPositive();
            return;
        }
        if (scene.start == WorldGap.Start.UNCLEAR) {
            return;
        }
        assertThat(scene.time).as("seed %d: touching, then leaving", seed).isGreaterThan(0);
        double foresight = GeometryImpl.DEFAULT_FORESIGHT;
        double oracle = wall ? scene.gap.firstFaceContact(foresight) : scene.gap.firstContact(foresight);
        if (oracle < Double.POSITIVE_INFINITY) {
            assertThat(scene.time).as("seed %d: oracle contact at %s", seed, oracle)
                    .isLessThanOrEqualTo(oracle + CONTACT);
        }
        if (scene.time < Double.POSITIVE_INFINITY) {
            double gap = wall ? scene.gap.faceGap(scene.time) : scene.gap.at(scene.time);
            assertThat(Math.abs(gap)).as("seed %d: gap at the reported time %s", seed, scene.time)
                    .isLessThanOrEqualTo(CONTACT);
        }
    }
}
