package physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.stream.LongStream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import physics.Geometry.VectPair;

/** Properties of the closed-form methods over random cases; each failure names its seed. */
class StaticPropertyTest {
    private static final double CONTACT = 1e-9;
    private static final double INF = Double.POSITIVE_INFINITY;

    static LongStream seeds() {
        return RandomScene.seeds(120);
    }

    /** Distance from the point to the segment's infinite line. */
    private static double lineDistance(LineSegment s, Vect p) {
        return Math.sqrt(p.distanceSquared(Geometry.perpendicularPointWholeLine(s, p)));
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void wallContactBuiltBackwardsIsFoundAtItsTime(long seed) {
        RandomScene r = new RandomScene(seed);
        LineSegment wall = new LineSegment(r.point(10), r.point(10));
        Vect foot = wall.p1().plus(wall.p2().minus(wall.p1()).times(r.between(0, 1)));
        Vect dir = wall.p2().minus(wall.p1()).unitSize();
        Vect normal = new Vect(-dir.y(), dir.x()).times(r.coin() ? 1 : -1);
        double radius = r.between(0.1, 1);
        Vect centreAtContact = foot.plus(normal.times(radius));
        // Any velocity with a part into the wall, run backwards for the expected time.
        Vect velocity = normal.times(-r.between(0.1, 20)).plus(dir.times(r.between(-20, 20)));
        double expected = r.between(0.01, 5);
        Circle ball = new Circle(centreAtContact.minus(velocity.times(expected)), radius);
        double t = Geometry.timeUntilWallCollision(wall, ball, velocity);
        assertThat(t).as("seed %d", seed).isCloseTo(expected, within(1e-9 * expected));
        Vect atContact = ball.getCenter().plus(velocity.times(t));
        assertThat(lineDistance(wall, atContact)).as("seed %d", seed).isCloseTo(radius, within(CONTACT));
        assertThat(Geometry.timeUntilWallCollision(wall, ball, velocity.neg())).as("seed %d: away", seed)
                .isEqualTo(INF);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void circleContactBuiltBackwardsIsFoundAtItsTime(long seed) {
        RandomScene r = new RandomScene(seed);
        Circle circle = new Circle(r.point(10), r.coin() ? 0 : r.between(0.1, 2));
        double radius = r.between(0.1, 1);
        Vect outward = r.vector(1, 1);
        Vect centreAtContact = circle.getCenter().plus(outward.times(circle.getRadius() + radius));
        Vect velocity = r.vector(0.1, 30);
        if (velocity.dot(outward) > 0) {
            velocity = velocity.minus(outward.times(2 * velocity.dot(outward)));
        }
        double expected = r.between(0.01, 5);
        Circle ball = new Circle(centreAtContact.minus(velocity.times(expected)), radius);
        double t = Geometry.timeUntilCircleCollision(circle, ball, velocity);
        assertThat(t).as("seed %d", seed).isCloseTo(expected, within(1e-9 * expected / Math.max(1e-3,
                -velocity.unitSize().dot(outward))));
        double distance = Math.sqrt(circle.getCenter().distanceSquared(ball.getCenter().plus(velocity.times(t))));
        assertThat(distance).as("seed %d", seed).isCloseTo(circle.getRadius() + radius, within(CONTACT));
        assertThat(Geometry.timeUntilCircleCollision(circle, ball, velocity.neg())).as("seed %d: away", seed)
                .isEqualTo(INF);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void ballBallContactIsAtTheSumOfRadiiOrNever(long seed) {
        RandomScene r = new RandomScene(seed);
        Circle a = new Circle(r.point(10), r.between(0.1, 1));
        Circle b;
        do { // apart at the start
            b = new Circle(r.point(10), r.between(0.1, 1));
        } while (Math.sqrt(a.getCenter().distanceSquared(b.getCenter())) <= a.getRadius() + b.getRadius());
        Vect va = r.vector(0, 20);
        Vect vb = r.vector(0, 20);
        double sum = a.getRadius() + b.getRadius();
        double t = Geometry.timeUntilBallBallCollision(a, va, b, vb);
        Vect relative = a.getCenter().minus(b.getCenter());
        Vect relativeVelocity = va.minus(vb);
        if (relative.dot(relativeVelocity) >= 0) {
            assertThat(t).as("seed %d: separating", seed).isEqualTo(INF);
        } else if (t < INF) {
            Vect gap = relative.plus(relativeVelocity.times(t));
            assertThat(gap.length()).as("seed %d", seed).isCloseTo(sum, within(CONTACT));
        } else {
            // Never: the closest approach of the centres is more than the sum of radii.
            double tClosest = -relative.dot(relativeVelocity) / relativeVelocity.dot(relativeVelocity);
            assertThat(relative.plus(relativeVelocity.times(tClosest)).length()).as("seed %d: miss", seed)
                    .isGreaterThan(sum);
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void elasticReflectionsKeepSpeedAndReflectingTwiceRestores(long seed) {
        RandomScene r = new RandomScene(seed);
        Vect v = r.vector(0, 30);
        LineSegment wall = new LineSegment(r.point(10), r.point(10));
        Vect offWall = Geometry.reflectWall(wall, v);
        assertThat(offWall.length()).as("seed %d", seed).isCloseTo(v.length(), within(1e-12));
        assertClose(Geometry.reflectWall(wall, offWall), v, seed);
        Vect centre = r.point(10);
        Vect ballCentre = centre.plus(r.vector(0.5, 2));
        Vect offCircle = Geometry.reflectCircle(centre, ballCentre, v);
        assertThat(offCircle.length()).as("seed %d", seed).isCloseTo(v.length(), within(1e-12));
        assertClose(Geometry.reflectCircle(centre, ballCentre, offCircle), v, seed);
        double coeff = r.between(0, 1);
        assertClose(Geometry.reflectWall(wall, v, coeff), Geometry.applyReflectionCoeff(v, offWall, coeff), seed);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void ballCollisionConservesMomentumAndEnergy(long seed) {
        RandomScene r = new RandomScene(seed);
        Vect c1 = r.point(10);
        Vect c2 = c1.plus(r.vector(0.5, 2));
        double m1 = r.between(0.1, 10);
        double m2 = r.between(0.1, 10);
        Vect v1 = r.vector(0, 30);
        Vect v2 = r.vector(0, 30);
        VectPair out = Geometry.reflectBalls(c1, m1, v1, c2, m2, v2);
        assertClose(out.v1.times(m1).plus(out.v2.times(m2)), v1.times(m1).plus(v2.times(m2)), seed);
        double before = m1 * v1.dot(v1) + m2 * v2.dot(v2);
        double after = m1 * out.v1.dot(out.v1) + m2 * out.v2.dot(out.v2);
        assertThat(after).as("seed %d: energy", seed).isCloseTo(before, within(1e-9 * before));
        VectPair back = Geometry.reflectBalls(c1, m1, out.v1, c2, m2, out.v2);
        assertClose(back.v1, v1, seed);
        assertClose(back.v2, v2, seed);
    }

    private static void assertClose(Vect actual, Vect expected, long seed) {
        assertThat(actual.minus(expected).length()).as("seed %d: %s vs %s", seed, actual, expected)
                .isLessThan(1e-10 * Math.max(1, expected.length()));
    }
}
