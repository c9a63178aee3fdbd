package physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.awt.geom.Line2D;
import java.awt.geom.Point2D;
import java.util.stream.IntStream;
import java.util.stream.LongStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import physics.Geometry.DoublePair;
import physics.Geometry.VectPair;

/**
 * Our own compatibility suite with the MIT package (issue 25): random and edge inputs for the API's methods, the
 * expected answers taken from {@code physics-contract.md} and from the mathematics, written out here. The
 * contract's rows one by one are {@link PhysicsContractTest}; the closed forms and the rotating search have their
 * own suites ({@link StaticPropertyTest}, {@link RotatingOracleTest}, {@link RotatingLimitTest}).
 */
class CompatibilityTest {
    private static final double INF = Double.POSITIVE_INFINITY;

    static LongStream seeds() {
        return RandomScene.seeds(200);
    }

    /** Any angle, far outside (-pi, pi] too. */
    private static double anyRadians(RandomScene r) {
        return r.coin() ? r.between(-4 * Math.PI, 4 * Math.PI) : r.between(-1e4, 1e4);
    }

    private static Vect integerPoint(RandomScene r) {
        return new Vect(Math.round(r.between(-1000, 1000)), Math.round(r.between(-1000, 1000)));
    }

    /** The integer point turned by k quarter turns (+x toward +y), by swapping and negating its coordinates. */
    private static Vect quarterTurns(Vect p, int k) {
        return switch (Math.floorMod(k, 4)) {
            case 0 -> p;
            case 1 -> new Vect(-p.y(), p.x());
            case 2 -> new Vect(-p.x(), -p.y());
            default -> new Vect(p.y(), -p.x());
        };
    }

    // --- Angle ---

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void radiansAreTheDirectionInMinusPiToPi(long seed) {
        double given = anyRadians(new RandomScene(seed));
        Angle a = new Angle(given);
        double radians = a.radians();
        assertThat(radians).as("seed %d: %s", seed, given).isGreaterThan(-Math.PI).isLessThanOrEqualTo(Math.PI);
        // The same direction: given - radians is a whole number of turns (to the rounding of given).
        double turns = (given - radians) / (2 * Math.PI);
        assertThat(turns).as("seed %d", seed).isCloseTo(Math.rint(turns), within(1e-12 * (1 + Math.abs(given))));
        assertThat(a.cos()).as("seed %d", seed).isEqualTo(StrictMath.cos(given));
        assertThat(a.sin()).as("seed %d", seed).isEqualTo(StrictMath.sin(given));
        assertThat(a.tan()).as("seed %d", seed).isEqualTo(a.sin() / a.cos());
        assertThat(a).hasToString("Angle(" + a.cos() + "," + a.sin() + ")");
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void anglesWholeTurnsApartAreEqualAndCompareAsEqual(long seed) {
        RandomScene r = new RandomScene(seed);
        double given = r.between(-Math.PI, Math.PI);
        int turns = (int) Math.round(r.between(-50, 50));
        Angle a = new Angle(given);
        Angle b = new Angle(given + turns * 2 * Math.PI);
        assertThat(a).as("seed %d", seed).isEqualTo(b).hasSameHashCodeAs(b);
        assertThat(a.compareTo(b)).as("seed %d", seed).isZero();
        Angle c = new Angle(given + 1e-3);
        assertThat(a).as("seed %d", seed).isNotEqualTo(c);
        assertThat(Integer.signum(a.compareTo(c))).as("seed %d: ordered by radians", seed)
                .isEqualTo(Integer.signum(Double.compare(a.radians(), c.radians())));
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void plusAndMinusAreTheSumAndDifferenceOfTheDirections(long seed) {
        RandomScene r = new RandomScene(seed);
        double x = anyRadians(r);
        double y = anyRadians(r);
        Angle sum = new Angle(x).plus(new Angle(y));
        Angle difference = new Angle(x).minus(new Angle(y));
        assertThat(sum).as("seed %d", seed).isEqualTo(new Angle(x + y));
        assertThat(difference).as("seed %d", seed).isEqualTo(new Angle(x - y));
        assertThat(Math.hypot(sum.cos(), sum.sin())).as("seed %d: a unit vector", seed).isCloseTo(1, within(1e-15));
    }

    @Test
    void quarterTurnsGivenInRadiansOrDegreesAreExact() {
        for (int k = -12; k <= 12; k++) {
            double[] ways = {Math.toRadians(90.0 * k), k * Math.PI / 2, k * (Math.PI / 2), Math.PI * k / 2};
            for (double radians : ways) {
                Angle a = new Angle(radians);
                Vect unit = quarterTurns(Vect.X_HAT, k);
                assertThat(a.cos()).as("%s quarter turns as %s rad", k, radians).isEqualTo(unit.x());
                assertThat(a.sin()).as("%s quarter turns as %s rad", k, radians).isEqualTo(unit.y());
            }
        }
        // Close to a quarter turn but not within rounding of it: an ordinary angle.
        assertThat(new Angle(Math.PI / 2 + 1e-12).cos()).isEqualTo(StrictMath.cos(Math.PI / 2 + 1e-12));
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void turningIntegerPointsByQuarterTurnsGivesIntegers(long seed) {
        RandomScene r = new RandomScene(seed);
        Angle[] constants = {Angle.ZERO, Angle.DEG_90, Angle.DEG_180, Angle.DEG_270};
        Vect pivot = integerPoint(r);
        for (int i = 0; i < 20; i++) {
            Vect p = integerPoint(r);
            for (int k = -8; k <= 8; k++) {
                Vect expected = pivot.plus(quarterTurns(p.minus(pivot), k));
                assertThat(Geometry.rotateAround(p, pivot, new Angle(Math.toRadians(90.0 * k))))
                        .as("seed %d: %s by %s quarter turns", seed, p, k).isEqualTo(expected);
                assertThat(p.rotateBy(new Angle(k * Math.PI / 2))).isEqualTo(quarterTurns(p, k));
            }
            for (int k = 0; k < 4; k++) {
                assertThat(p.rotateBy(constants[k])).as("seed %d", seed).isEqualTo(quarterTurns(p, k));
            }
            LineSegment s = new LineSegment(p, integerPoint(r));
            LineSegment turned = Geometry.rotateAround(s, pivot, Angle.DEG_270);
            assertThat(turned).isEqualTo(new LineSegment(pivot.plus(quarterTurns(s.p1().minus(pivot), 3)),
                    pivot.plus(quarterTurns(s.p2().minus(pivot), 3))));
            Circle c = new Circle(p, r.between(0, 2));
            assertThat(Geometry.rotateAround(c, pivot, Angle.DEG_180))
                    .isEqualTo(new Circle(pivot.plus(quarterTurns(p.minus(pivot), 2)), c.getRadius()));
        }
    }

    @Test
    void eighthTurnConstantsAreCorrectlyRoundedAndSumToQuarterTurns() {
        double h = Math.sqrt(0.5);
        assertThat(Angle.DEG_45.cos()).isEqualTo(h);
        assertThat(Angle.DEG_45.plus(Angle.DEG_45)).isEqualTo(Angle.DEG_90);
        assertThat(Angle.DEG_45.plus(Angle.DEG_45).cos()).isEqualTo(0.0);
        assertThat(Angle.DEG_135.plus(Angle.DEG_135).sin()).isEqualTo(-1.0);
        assertThat(Angle.DEG_315.minus(Angle.DEG_45).radians()).isEqualTo(-Math.PI / 2);
    }

    @Test
    void theVectorAngleIsItsDirection() {
        assertThat(new Vect(0, 5).angle()).isEqualTo(Angle.DEG_90);
        assertThat(new Vect(0, 5).angle().cos()).isEqualTo(0.0);
        assertThat(new Vect(-2, -2).angle().radians()).isEqualTo(-3 * Math.PI / 4);
        assertThat(new Angle(-7, 0).radians()).isEqualTo(Math.PI);
        assertThatThrownBy(() -> new Angle(0.0, -0.0)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(Vect.ZERO::angle).isInstanceOf(IllegalArgumentException.class);
    }

    // --- Vect and the shapes ---

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void vectArithmeticIsComponentwiseAndPrintsAsThePackage(long seed) {
        RandomScene r = new RandomScene(seed);
        Vect a = r.point(100);
        Vect b = r.point(100);
        double k = r.between(-10, 10);
        assertThat(a.plus(b)).isEqualTo(new Vect(a.x() + b.x(), a.y() + b.y()));
        assertThat(a.minus(b)).isEqualTo(new Vect(a.x() - b.x(), a.y() - b.y()));
        assertThat(a.times(k)).isEqualTo(new Vect(a.x() * k, a.y() * k));
        assertThat(a.neg()).isEqualTo(new Vect(-a.x(), -a.y()));
        assertThat(a.dot(b)).isEqualTo(a.x() * b.x() + a.y() * b.y());
        double dx = a.x() - b.x();
        double dy = a.y() - b.y();
        assertThat(a.distanceSquared(b)).isEqualTo(dx * dx + dy * dy);
        assertThat(Geometry.distanceSquared(a, b)).isEqualTo(a.distanceSquared(b));
        assertThat(Geometry.distanceSquared(a.x(), a.y(), b.x(), b.y())).isEqualTo(b.distanceSquared(a));
        assertThat(a.length()).isEqualTo(Math.hypot(a.x(), a.y()));
        assertThat(a.unitSize().length()).isCloseTo(1, within(1e-15));
        Vect onB = a.projectOn(b);
        assertThat(a.minus(onB).dot(b)).as("seed %d: the rest is orthogonal", seed)
                .isCloseTo(0, within(1e-9 * a.length() * b.length()));
        assertThat(a).hasToString("<" + a.x() + "," + a.y() + ">");
        assertThat(new Vect(new Point2D.Double(a.x(), a.y()))).isEqualTo(a).hasSameHashCodeAs(a);
        assertThat(a.toPoint2D()).isEqualTo(new Point2D.Double(a.x(), a.y()));
        Angle turn = new Angle(anyRadians(r));
        assertThat(a.rotateBy(turn)).isEqualTo(new Vect(a.x() * turn.cos() - a.y() * turn.sin(),
                a.x() * turn.sin() + a.y() * turn.cos()));
        assertThat(new Vect(turn, k)).isEqualTo(new Vect(turn.cos() * k, turn.sin() * k));
        assertThat(new Vect(turn)).isEqualTo(new Vect(turn.cos(), turn.sin()));
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void shapesPrintAndCompareAsThePackage(long seed) {
        RandomScene r = new RandomScene(seed);
        Vect p = r.point(100);
        Vect q = r.point(100);
        double radius = r.between(0, 3);
        LineSegment s = new LineSegment(p, q);
        assertThat(s).hasToString("LineSegment(" + p + "-" + q + ")")
                .isEqualTo(new LineSegment(p.x(), p.y(), q.x(), q.y()))
                .isEqualTo(new LineSegment(new Line2D.Double(p.x(), p.y(), q.x(), q.y())))
                .hasSameHashCodeAs(new LineSegment(p.x(), p.y(), q.x(), q.y()));
        assertThat(s.length()).isEqualTo(q.minus(p).length());
        assertThat(s.angle()).isEqualTo(q.minus(p).angle());
        Circle c = new Circle(p, radius);
        assertThat(c).hasToString("[Circle center=" + p + " radius=" + radius + "]")
                .isEqualTo(new Circle(p.x(), p.y(), radius)).hasSameHashCodeAs(new Circle(p.x(), p.y(), radius));
        assertThat(new DoublePair(p.x(), q.y())).hasToString("[" + p.x() + "," + q.y() + "]")
                .isEqualTo(new DoublePair(p.x(), q.y()));
        assertThat(new DoublePair(p.x())).isEqualTo(new DoublePair(p.x(), p.x()));
        assertThat(new VectPair(p, q)).hasToString("[" + p + "," + q + "]").isEqualTo(new VectPair(p, q))
                .hasSameHashCodeAs(new VectPair(p, q));
    }

    @Test
    void constructorsAcceptAndRefuseAsThePackage() {
        assertThat(new Vect(Double.NaN, Double.POSITIVE_INFINITY)).hasToString("<NaN,Infinity>");
        assertThat(new LineSegment(new Vect(2, 3), new Vect(2, 3)).length()).isZero();
        assertThat(new Circle(Vect.ZERO, -1).getRadius()).isEqualTo(-1);
        assertThat(new Angle(Double.NaN).radians()).isNaN();
        assertThatThrownBy(() -> new Angle(0, 0)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new LineSegment(5, 5, 5, 5).angle()).isInstanceOf(IllegalArgumentException.class);
        assertThat(new DoublePair(Double.NaN).areFinite()).isFalse();
        assertThat(Geometry.DOUBLE_PAIR_NAN).isEqualTo(new DoublePair(Double.NaN, Double.NaN));
    }

    // --- Half-open faces ---

    /**
     * Axis-aligned faces with integer ends, so that a foot lands exactly on an end: a ball coming straight down
     * onto the face at a random point of [p1, p2) is met after (distance - radius) / speed; at p2, and beyond either
     * end, the face reports nothing. The face's direction decides which end is open.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void facesAreHalfOpenFromP1ToP2(long seed) {
        RandomScene r = new RandomScene(seed);
        int x1 = (int) Math.round(r.between(-20, 20));
        int length = (int) Math.round(r.between(1, 10));
        int x2 = r.coin() ? x1 + length : x1 - length;
        int y = (int) Math.round(r.between(-20, 20));
        boolean vertical = r.coin();
        LineSegment face = vertical ? new LineSegment(y, x1, y, x2) : new LineSegment(x1, y, x2, y);
        double radius = 0.25 * Math.round(r.between(1, 4));
        double gap = Math.round(r.between(1, 8));
        double speed = 0.5 * Math.round(r.between(1, 8));
        double expected = gap / speed;
        double along = r.coin() ? x1 : x1 + (x2 - x1) * r.between(0, 1);
        for (double foot : new double[] {along, x1, x2, x2 + Math.signum(x2 - x1) * 0.5, x1 - Math.signum(x2 - x1)
                * 0.5}) {
            double from = y - gap - radius;
            Circle ball = vertical ? new Circle(from, foot, radius) : new Circle(foot, from, radius);
            Vect velocity = vertical ? new Vect(speed, 0) : new Vect(0, speed);
            boolean onFace = (foot - x1) * (x2 - x1) >= 0 && (x2 - foot) * (x2 - x1) > 0;
            assertThat(Geometry.timeUntilWallCollision(face, ball, velocity)).as("seed %d: foot at %s of %s", seed,
                    foot, face).isEqualTo(onFace ? expected : INF);
            assertThat(Geometry.timeUntilRotatingWallCollision(face, new Vect(3, 4), 0.0, ball, velocity))
                    .isEqualTo(onFace ? expected : INF);
        }
    }

    // --- Rotating reflection as the package answers it ---

    /**
     * A ball anywhere with its foot on the segment, touching, off the face or overlapping it: the velocity relative
     * to the surface at the foot, w J (foot - pivot), reflected off the line with the coefficient, plus the surface
     * velocity. A foot beyond an end: the velocity unchanged.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void reflectRotatingWallAnswersAtTheFootOrGivesTheVelocityBack(long seed) {
        RandomScene r = new RandomScene(seed);
        Vect pivot = r.point(5);
        LineSegment segment = new LineSegment(r.point(5), r.point(5));
        double w = r.between(-20, 20);
        Vect v = r.vector(0, 30);
        double coefficient = r.coin() ? 1 : r.between(0, 1);
        Vect dir = segment.p2().minus(segment.p1());
        Vect unit = dir.unitSize();
        Vect normal = new Vect(-unit.y(), unit.x());
        double fraction = r.coin() ? r.between(0, 1) : r.coin() ? r.between(-1, -1e-3) : r.between(1 + 1e-3, 2);
        Vect foot = segment.p1().plus(dir.times(fraction));
        Circle ball = new Circle(foot.plus(normal.times(r.between(-1, 1))), r.between(0.1, 0.5));
        Vect out = Geometry.reflectRotatingWall(segment, pivot, w, ball, v, coefficient);
        if (fraction < 0 || fraction > 1) {
            assertThat(out).as("seed %d: beyond an end", seed).isEqualTo(v);
            return;
        }
        Vect surface = new Vect(-(foot.y() - pivot.y()), foot.x() - pivot.x()).times(w);
        Vect relative = v.minus(surface);
        double normalPart = relative.dot(normal);
        Vect expected = relative.minus(normal.times((1 + coefficient) * normalPart)).plus(surface);
        double scale = 1e-12 * (1 + v.length() + surface.length());
        assertThat(out.x()).as("seed %d", seed).isCloseTo(expected.x(), within(scale));
        assertThat(out.y()).as("seed %d", seed).isCloseTo(expected.y(), within(scale));
        if (coefficient == 1) {
            assertThat(out).isEqualTo(Geometry.reflectRotatingWall(segment, pivot, w, ball, v));
        }
    }

    // --- Angular velocity exactly 0 ---

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void everyRotatingMethodAtAngularVelocityZeroIsItsStaticMethod(long seed) {
        RandomScene r = new RandomScene(seed);
        LineSegment segment = new LineSegment(r.point(5), r.point(5));
        Circle circle = new Circle(r.point(5), r.coin() ? 0 : r.between(0, 1));
        Circle ball = new Circle(r.point(8), r.between(0.1, 0.5));
        Vect v = r.vector(0, 30);
        Vect pivot = r.point(5);
        double coefficient = r.between(0, 1);
        double w = r.coin() ? 0.0 : -0.0;
        assertThat(Geometry.timeUntilRotatingWallCollision(segment, pivot, w, ball, v)).as("seed %d", seed)
                .isEqualTo(Geometry.timeUntilWallCollision(segment, ball, v));
        assertThat(Geometry.timeUntilRotatingCircleCollision(circle, pivot, w, ball, v)).as("seed %d", seed)
                .isEqualTo(Geometry.timeUntilCircleCollision(circle, ball, v));
        assertThat(Geometry.reflectRotatingWall(segment, pivot, w, ball, v))
                .isEqualTo(Geometry.reflectWall(segment, v));
        assertThat(Geometry.reflectRotatingWall(segment, pivot, w, ball, v, coefficient))
                .isEqualTo(Geometry.reflectWall(segment, v, coefficient));
        assertThat(Geometry.reflectRotatingCircle(circle, pivot, w, ball, v))
                .isEqualTo(Geometry.reflectCircle(circle.getCenter(), ball.getCenter(), v));
        assertThat(Geometry.reflectRotatingCircle(circle, pivot, w, ball, v, coefficient))
                .isEqualTo(Geometry.reflectCircle(circle.getCenter(), ball.getCenter(), v, coefficient));
    }

    // --- The other static methods on edge inputs ---

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void quadraticSolutionsAreTheRootsTheyWereBuiltFrom(long seed) {
        RandomScene r = new RandomScene(seed);
        double root1 = r.between(-100, 100);
        double root2 = root1 + (r.coin() ? 1 : -1) * r.between(0.1, 100);
        double a = r.coin() ? r.between(0.1, 10) : -r.between(0.1, 10);
        DoublePair roots = Geometry.quadraticSolution(a, -a * (root1 + root2), a * root1 * root2);
        double small = Math.min(root1, root2);
        double large = Math.max(root1, root2);
        double tolerance = 1e-12 * (1 + Math.abs(small) + Math.abs(large)) * (1 + Math.abs(large) / (large - small));
        assertThat(roots.d1).as("seed %d", seed).isCloseTo(small, within(tolerance));
        assertThat(roots.d2).as("seed %d", seed).isCloseTo(large, within(tolerance));
        assertThat(Geometry.minQuadraticSolution(a, -a * (root1 + root2), a * root1 * root2)).isEqualTo(roots.d1);
        assertThat(Geometry.quadraticSolution(a, 0, a)).as("no real root").isEqualTo(Geometry.DOUBLE_PAIR_NAN);
        assertThat(Geometry.quadraticSolution(0, a, -a * root1).d1).as("linear").isCloseTo(root1, within(1e-12 * (1
                + Math.abs(root1))));
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void feetOfPerpendicularsAreOrthogonalAndOnTheClosedSegment(long seed) {
        RandomScene r = new RandomScene(seed);
        LineSegment s = new LineSegment(r.point(10), r.point(10));
        Vect p = r.point(15);
        Vect dir = s.p2().minus(s.p1());
        Vect whole = Geometry.perpendicularPointWholeLine(s, p);
        assertThat(p.minus(whole).dot(dir)).as("seed %d", seed).isCloseTo(0, within(1e-9 * dir.length()
                * (1 + p.minus(whole).length())));
        double fraction = whole.minus(s.p1()).dot(dir) / dir.dot(dir);
        Vect foot = Geometry.perpendicularPoint(s, p);
        if (fraction < -1e-12 || fraction > 1 + 1e-12) {
            assertThat(foot).as("seed %d", seed).isNull();
        } else if (fraction > 1e-12 && fraction < 1 - 1e-12) {
            assertThat(foot).as("seed %d", seed).isEqualTo(whole);
        }
        assertThat(Geometry.perpendicularPoint(s, s.p2())).as("ends included").isNotNull();
        assertThat(Geometry.perpendicularPoint(s, s.p1())).as("ends included").isEqualTo(s.p1());
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void reflectionsKeepTheTangentialPartAndScaleTheNormalOne(long seed) {
        RandomScene r = new RandomScene(seed);
        LineSegment wall = new LineSegment(r.point(10), r.point(10));
        Vect v = r.vector(0, 30);
        double coefficient = r.between(0, 1);
        Vect unit = wall.p2().minus(wall.p1()).unitSize();
        Vect normal = new Vect(-unit.y(), unit.x());
        Vect out = Geometry.reflectWall(wall, v, coefficient);
        double scale = 1e-12 * (1 + v.length());
        assertThat(out.dot(unit)).as("seed %d", seed).isCloseTo(v.dot(unit), within(scale));
        assertThat(out.dot(normal)).as("seed %d", seed).isCloseTo(-coefficient * v.dot(normal), within(scale));
        Vect perfect = Geometry.reflectWall(wall, v);
        Vect damped = Geometry.applyReflectionCoeff(v, perfect, coefficient);
        assertThat(damped.minus(out).length()).as("seed %d", seed).isLessThan(scale);
        Vect centre = r.point(10);
        Vect ballCentre = centre.plus(r.vector(0.5, 2));
        Vect radial = ballCentre.minus(centre).unitSize();
        Vect offCircle = Geometry.reflectCircle(centre, ballCentre, v, coefficient);
        assertThat(offCircle.dot(radial)).as("seed %d", seed).isCloseTo(-coefficient * v.dot(radial), within(scale));
    }

    @Test
    void zeroTimesAndTouchingBallsAtTheEdges() {
        Circle ball = new Circle(0, 1, 1);
        LineSegment floor = new LineSegment(-1, 0, 1, 0);
        assertThat(Geometry.timeUntilWallCollision(floor, ball, new Vect(0, -1))).as("touching, closing").isZero();
        assertThat(Geometry.timeUntilWallCollision(floor, ball, new Vect(0, 1))).as("touching, leaving")
                .isEqualTo(INF);
        assertThat(Geometry.timeUntilBallBallCollision(ball, new Vect(0, -1), new Circle(0, -1, 1), Vect.ZERO))
                .isZero();
        assertThat(Geometry.timeUntilCircleCollision(new Circle(0, 0, 0), new Vect(0, 2), new Vect(0, -1)))
                .isEqualTo(new DoublePair(2));
        assertThat(IntStream.rangeClosed(-3, 3).mapToObj(k -> new Angle(k * Math.PI).sin()).distinct().toList())
                .containsExactly(0.0);
    }
}
