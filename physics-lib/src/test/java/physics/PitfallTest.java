package physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.LongStream;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** One nested class per item 1-10 of PHYSICS-PITFALLS.md, named after it. */
class PitfallTest {
    private static final double INF = Double.POSITIVE_INFINITY;
    private static final double FLIPPER_SPEED = Math.toRadians(1080);
    private static final LineSegment FLIPPER = new LineSegment(0, 0, 2, 0);

    static LongStream seeds() {
        return RandomScene.seeds(60);
    }

    @Nested
    class Pitfall01RotatingSegmentMissesContactsNearItsEnds {
        @ParameterizedTest(name = "seed {0}")
        @MethodSource("physics.PitfallTest#seeds")
        void fastFlipperTipGrazingABallIsFoundLikeTheOracle(long seed) {
            // Balls placed just beyond the tip's circle of 2 L, so only the region around the tip can touch them.
            RandomScene r = new RandomScene(seed);
            Vect velocity = r.coin() ? Vect.ZERO : r.vector(0, 10);
            Circle ball;
            WorldGap gap;
            do { // clear of the flipper at the start
                double radius = r.between(0.1, 0.5);
                ball = new Circle(new Vect(new Angle(r.between(0.2, 1.4)), 2 + radius * r.between(-0.3, 0.95)),
                        radius);
                gap = WorldGap.wall(FLIPPER, Vect.ZERO, FLIPPER_SPEED, ball, velocity);
            } while (gap.at(0) <= 0);
            // The face and a zero-radius circle at the tip together: the segment as a flipper is built.
            double t = Math.min(
                    Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, FLIPPER_SPEED, ball, velocity),
                    Geometry.timeUntilRotatingCircleCollision(new Circle(FLIPPER.p2(), 0), Vect.ZERO, FLIPPER_SPEED,
                            ball, velocity));
            RotatingOracleTest.assertAgreesWithOracle(seed, gap, t);
        }

        @Test
        void tipContactWithTheFootOffTheSegment() {
            // The foot is off the segment at contact: not the face's (as for the static face), the tip circle's.
            double angle = Math.atan2(1, 2.2) - Math.acos((5.84 + 4 - 0.25) / (4 * Math.sqrt(5.84)));
            Circle ball = new Circle(2.2, 1, 0.5);
            assertThat(Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, FLIPPER_SPEED, ball, Vect.ZERO))
                    .isEqualTo(INF);
            double t = Geometry.timeUntilRotatingCircleCollision(new Circle(2, 0, 0), Vect.ZERO, FLIPPER_SPEED, ball,
                    Vect.ZERO);
            assertThat(t).isCloseTo(angle / FLIPPER_SPEED, within(1e-10));
        }
    }

    @Nested
    class Pitfall02BallAtRestIsInvisibleToARotatingObstacle {
        @ParameterizedTest(name = "seed {0}")
        @MethodSource("physics.PitfallTest#seeds")
        void flipperSwingingIntoAnyRestingBallInItsSweepFindsIt(long seed) {
            // A ball resting anywhere in the quarter-disc the flipper sweeps in its first 90 degrees.
            RandomScene r = new RandomScene(seed);
            Circle ball;
            WorldGap gap;
            do { // clear of the flipper at the start
                ball = new Circle(new Vect(new Angle(r.between(0.3, 1.5)), r.between(0.2, 2)), r.between(0.1, 0.5));
                gap = WorldGap.wall(FLIPPER, Vect.ZERO, FLIPPER_SPEED, ball, Vect.ZERO);
            } while (gap.at(0) <= 0);
            double t = Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, FLIPPER_SPEED, ball, Vect.ZERO);
            assertThat(t).as("seed %d", seed).isLessThan(0.25 / FLIPPER_SPEED * 2 * Math.PI);
            RotatingOracleTest.assertAgreesWithOracle(seed, gap, t);
        }

        @Test
        void restingBallAndRotatingCircle() {
            double t = Geometry.timeUntilRotatingCircleCollision(new Circle(2, 0, 0.25), Vect.ZERO, FLIPPER_SPEED,
                    new Circle(0, 2, 0.25), Vect.ZERO);
            assertThat(t).isCloseTo(Math.asin(31.0 / 32) / FLIPPER_SPEED, within(1e-10));
        }
    }

    @Nested
    class Pitfall03RotationIsAssumedToLastForEver {
        private final double sweepTime = (Math.PI / 2) / FLIPPER_SPEED;
        private final Circle behind = new Circle(1, -1.5, 0.5);

        @Test
        void aContactAfterTheFlipperStopsIsCutOffByTheForesightOfAnInstance() {
            assertThat(Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, FLIPPER_SPEED, behind, Vect.ZERO))
                    .as("turning for ever it would come round to the ball").isGreaterThan(sweepTime).isFinite();
            GeometryImpl duringSweep = new GeometryImpl(sweepTime, GeometryImpl.DEFAULT_SEARCH_SLICES);
            assertThat(duringSweep.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, FLIPPER_SPEED, behind,
                    Vect.ZERO)).isEqualTo(INF);
        }

        @Test
        void afterTheSweepTheFlipperIsStaticAtItsStopAngle() {
            GeometryImpl duringSweep = new GeometryImpl(sweepTime, GeometryImpl.DEFAULT_SEARCH_SLICES);
            Circle ball = new Circle(3, 1, 0.5);
            Vect velocity = new Vect(-10, 0);
            assertThat(duringSweep.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, FLIPPER_SPEED, ball, velocity))
                    .isEqualTo(INF);
            LineSegment stopped = Geometry.rotateAround(FLIPPER, Vect.ZERO, Angle.DEG_90);
            Circle ballAtStop = new Circle(ball.getCenter().plus(velocity.times(sweepTime)), 0.5);
            assertThat(Geometry.timeUntilWallCollision(stopped, ballAtStop, velocity))
                    .isCloseTo((3 - 10 * sweepTime - 0.5) / 10, within(1e-12));
        }

        @Test
        void aContactInsideTheSweepIsStillFound() {
            GeometryImpl duringSweep = new GeometryImpl(sweepTime, GeometryImpl.DEFAULT_SEARCH_SLICES);
            double angle = Math.acos(0.5 / Math.sqrt(3.25)) - Math.atan2(2, 3);
            assertThat(duringSweep.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, FLIPPER_SPEED,
                    new Circle(1, 1.5, 0.5), Vect.ZERO)).isCloseTo(angle / FLIPPER_SPEED, within(1e-10));
        }
    }

    @Nested
    class Pitfall04OverlappingBallGetsNever {
        @Test
        void overlappingAndClosingIsNowForEveryObstacle() {
            Circle sunk = new Circle(1, 0.45, 0.5);
            Vect down = new Vect(0.5, -1);
            assertThat(Geometry.timeUntilWallCollision(FLIPPER, sunk, down)).isZero();
            assertThat(Geometry.timeUntilCircleCollision(new Circle(1, 0, 0), sunk, down)).isZero();
            assertThat(Geometry.timeUntilBallBallCollision(sunk, down, new Circle(1, -0.5, 0.5), Vect.ZERO)).isZero();
            assertThat(Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 0, sunk, down)).isZero();
            assertThat(Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 5, sunk, Vect.ZERO)).isZero();
            assertThat(Geometry.timeUntilRotatingCircleCollision(new Circle(1, 0, 0), Vect.ZERO, 5, sunk, Vect.ZERO))
                    .isZero();
        }

        @Test
        void overlappingAndLeavingIsNever() {
            Circle sunk = new Circle(1, 0.45, 0.5);
            Vect up = new Vect(0.5, 1);
            assertThat(Geometry.timeUntilWallCollision(FLIPPER, sunk, up)).isEqualTo(INF);
            assertThat(Geometry.timeUntilCircleCollision(new Circle(1, 0, 0), sunk, up)).isEqualTo(INF);
            assertThat(Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 0, sunk, up)).isEqualTo(INF);
        }

        @Test
        void closingIsJudgedFromTheCurrentPositionNotFromAnEarlierRoot() {
            // Deep inside the circle and moving further in: the entry root lies in the past, but it is closing now.
            Circle deep = new Circle(0.3, 0, 0.5);
            assertThat(Geometry.timeUntilCircleCollision(new Circle(0, 0, 1), deep, new Vect(-1, 0))).isZero();
        }
    }

    @Nested
    class Pitfall05HalfOpenSegments {
        @Test
        void aContactAtP1IsTheFacesAndOneAtP2IsNot() {
            LineSegment forward = new LineSegment(0, 0, 4, 0);
            LineSegment backward = new LineSegment(4, 0, 0, 0);
            Vect down = new Vect(0, -2);
            Circle atZero = new Circle(0, 3, 1);
            Circle atFour = new Circle(4, 3, 1);
            assertThat(Geometry.timeUntilWallCollision(forward, atZero, down)).isEqualTo(1);
            assertThat(Geometry.timeUntilWallCollision(forward, atFour, down)).isEqualTo(INF);
            assertThat(Geometry.timeUntilWallCollision(backward, atFour, down)).isEqualTo(1);
            assertThat(Geometry.timeUntilWallCollision(backward, atZero, down)).isEqualTo(INF);
            // Two faces meeting at a corner: exactly one of them reports the ball that comes down on it.
            LineSegment left = new LineSegment(-4, 0, 0, 0);
            assertThat(Geometry.timeUntilWallCollision(left, atZero, down)).isEqualTo(INF);
            assertThat(Geometry.perpendicularPoint(forward, new Vect(4, 3))).isEqualTo(new Vect(4, 0));
        }

        @ParameterizedTest(name = "seed {0}")
        @MethodSource("physics.PitfallTest#seeds")
        void swappingTheEndsChangesNothing(long seed) {
            RandomScene r = new RandomScene(seed);
            LineSegment s = new LineSegment(r.point(5), r.point(5));
            LineSegment swapped = new LineSegment(s.p2(), s.p1());
            Circle ball = new Circle(r.point(5), r.between(0.1, 0.5));
            Vect v = r.vector(0, 20);
            Vect pivot = r.point(5);
            double w = r.between(-20, 20);
            assertThat(Geometry.timeUntilWallCollision(swapped, ball, v)).as("seed %d", seed)
                    .isCloseTo(Geometry.timeUntilWallCollision(s, ball, v), within(1e-12));
            assertThat(Geometry.perpendicularPoint(swapped, ball.getCenter()) == null).as("seed %d", seed)
                    .isEqualTo(Geometry.perpendicularPoint(s, ball.getCenter()) == null);
            assertThat(Geometry.timeUntilRotatingWallCollision(swapped, pivot, w, ball, v)).as("seed %d", seed)
                    .isCloseTo(Geometry.timeUntilRotatingWallCollision(s, pivot, w, ball, v), within(1e-9));
        }

        @Test
        void cornersAreZeroRadiusCirclesThatMeetTheFaceContactExactly() {
            // A ball falling at the end x = 0 touches face and corner circle at the same moment; at x = 4, the open
            // end, only the corner circle reports it.
            Vect down = new Vect(0, -2);
            LineSegment face = new LineSegment(0, 0, 4, 0);
            Circle atP1 = new Circle(0, 3, 1);
            assertThat(Geometry.timeUntilCircleCollision(new Circle(0, 0, 0), atP1, down))
                    .isCloseTo(Geometry.timeUntilWallCollision(face, atP1, down), within(1e-12));
            assertThat(Geometry.timeUntilCircleCollision(new Circle(4, 0, 0), new Circle(4, 3, 1), down))
                    .isCloseTo(1, within(1e-12));
        }
    }

    @Nested
    class Pitfall06AccuracyFarFromContact {
        @ParameterizedTest(name = "seed {0}")
        @MethodSource("physics.PitfallTest#seeds")
        void farCircleContactsAreWithin1e13OfTheSumOfRadii(long seed) {
            RandomScene r = new RandomScene(seed);
            Circle circle = new Circle(r.point(1), r.between(0, 0.5));
            Vect direction = r.vector(1, 1);
            Circle ball = new Circle(circle.getCenter().plus(direction.times(r.between(3, 20))), r.between(0.1, 0.5));
            // Aimed just inside the edge: a glancing contact, where the discriminant cancels worst.
            double sum = circle.getRadius() + ball.getRadius();
            Vect edge = circle.getCenter().plus(new Vect(-direction.y(), direction.x()).times(sum * 0.999));
            Vect velocity = edge.minus(ball.getCenter()).unitSize().times(r.between(1, 50));
            double t = Geometry.timeUntilCircleCollision(circle, ball, velocity);
            Vect at = ball.getCenter().plus(velocity.times(t));
            assertThat(Math.sqrt(at.distanceSquared(circle.getCenter()))).as("seed %d", seed)
                    .isCloseTo(sum, within(1e-13));
            Circle other = new Circle(ball.getCenter().plus(velocity.times(2 * t)), ball.getRadius());
            double tb = Geometry.timeUntilBallBallCollision(ball, velocity, other, velocity.neg());
            Vect a = ball.getCenter().plus(velocity.times(tb));
            Vect b = other.getCenter().minus(velocity.times(tb));
            assertThat(Math.sqrt(a.distanceSquared(b))).as("seed %d", seed).isCloseTo(2 * ball.getRadius(),
                    within(1e-13));
        }

        @Test
        void farWallContactIsWithin1e13() {
            LineSegment wall = new LineSegment(-100, 0, 100, 0);
            Circle ball = new Circle(0.1, 37.3, 0.5);
            Vect velocity = new Vect(0.3, -7.1);
            double t = Geometry.timeUntilWallCollision(wall, ball, velocity);
            assertThat(ball.getCenter().y() + velocity.y() * t).isCloseTo(0.5, within(1e-13));
        }
    }

    @Nested
    class Pitfall07HiddenStateInValueTypes {
        @ParameterizedTest(name = "seed {0}")
        @MethodSource("physics.PitfallTest#seeds")
        void resultsDoNotDependOnWhichAccessorRanFirst(long seed) {
            RandomScene r = new RandomScene(seed);
            Vect v = new Vect(new Angle(r.between(0, 7)), r.between(0, 10));
            Vect w = new Vect(v.x(), v.y());
            Vect other = r.point(5);
            v.angle();
            v.length();
            assertThat(v).as("seed %d", seed).isEqualTo(w).hasSameHashCodeAs(w);
            assertThat(v.dot(other)).isEqualTo(w.dot(other));
            assertThat(v.projectOn(other)).isEqualTo(w.projectOn(other));
            assertThat(v.rotateBy(Angle.DEG_45)).isEqualTo(w.rotateBy(Angle.DEG_45));
        }

        @Test
        void equalValuesAreOneSetElement() {
            Set<Object> set = new HashSet<>(List.of(new Vect(1, -0.0), new Angle(Math.PI), new Circle(0, 0, 1),
                    new LineSegment(0, 0, 1, 1)));
            assertThat(set).contains(new Vect(1, 0), Angle.DEG_180, new Circle(Vect.ZERO, 1),
                    new LineSegment(Vect.ZERO, new Vect(1, 1)));
        }

        @Test
        void sharedBetweenThreadsGivesTheSameAnswers() throws Exception {
            Circle ball = new Circle(1, 1.5, 0.5);
            double expected = new GeometryImpl().timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 3, ball,
                    Vect.ZERO);
            ExecutorService pool = Executors.newFixedThreadPool(4);
            try {
                List<Future<Double>> results = new ArrayList<>();
                for (int i = 0; i < 16; i++) {
                    results.add(pool.submit(() -> Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 3, ball,
                            Vect.ZERO)));
                }
                for (Future<Double> result : results) {
                    assertThat(result.get()).isEqualTo(expected);
                }
            } finally {
                pool.shutdownNow();
            }
        }
    }

    @Nested
    class Pitfall08DegenerateInput {
        @Test
        void whatThePackageAcceptsGetsADefinedAnswerNotAnException() {
            LineSegment point = new LineSegment(1, 1, 1, 1);
            Circle ball = new Circle(1, 2, 0.5);
            assertThat(Geometry.timeUntilWallCollision(point, ball, new Vect(0, -1))).as("no face").isEqualTo(INF);
            assertThat(Geometry.timeUntilRotatingWallCollision(point, Vect.ZERO, 1, ball, new Vect(0, -1)))
                    .isEqualTo(INF);
            assertThat(Geometry.reflectWall(point, Vect.X_HAT)).isEqualTo(Vect.X_HAT);
            assertThat(Geometry.reflectRotatingWall(point, Vect.ZERO, 1, ball, Vect.X_HAT)).isEqualTo(Vect.X_HAT);
            assertThat(Geometry.perpendicularPoint(point, new Vect(5, 5))).isEqualTo(new Vect(1, 1));
            assertThatThrownBy(point::angle).isInstanceOf(IllegalArgumentException.class);
            Geometry.VectPair unchanged = new Geometry.VectPair(Vect.X_HAT, Vect.ZERO);
            assertThat(Geometry.reflectBalls(Vect.ZERO, 0, Vect.X_HAT, Vect.ZERO, 0, Vect.ZERO)).as("no mass")
                    .isEqualTo(unchanged);
            assertThat(Geometry.reflectBalls(Vect.ZERO, 1, Vect.X_HAT, Vect.ZERO, 1, Vect.ZERO)).as("no normal")
                    .isEqualTo(unchanged);
            assertThat(Geometry.reflectCircle(Vect.ZERO, Vect.ZERO, Vect.X_HAT)).isEqualTo(Vect.X_HAT);
            assertThat(Geometry.reflectRotatingCircle(new Circle(0, 0, 0), Vect.X_HAT, 1, new Circle(0, 0, 0.5),
                    Vect.X_HAT)).isEqualTo(Vect.X_HAT);
            assertThat(Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, Double.NaN, new Circle(5, 5, 1),
                    Vect.ZERO)).isEqualTo(INF);
            assertThat(Geometry.timeUntilRotatingCircleCollision(new Circle(0, 0, 0), Vect.ZERO, 1,
                    new Circle(Double.NaN, 5, 1), Vect.ZERO)).isEqualTo(INF);
            assertThat(Geometry.quadraticSolution(0, 0, 0)).as("every number a root").isEqualTo(
                    Geometry.DOUBLE_PAIR_NAN);
            assertThatThrownBy(() -> new GeometryImpl(0, 4)).isInstanceOf(IllegalArgumentException.class);
            assertThatThrownBy(() -> new GeometryImpl(1, 0)).isInstanceOf(IllegalArgumentException.class);
        }

        @Test
        void subnormalSpeedTowardAWallGivesInfinityNotNaN() {
            // 1 L at 1e-320 L/s is 1e320 s away: beyond the doubles, so infinity, not a NaN centre at contact.
            LineSegment floor = new LineSegment(0, 20, 20, 20);
            assertThat(Geometry.timeUntilWallCollision(floor, new Circle(10, 18.75, 0.25), new Vect(0, 1e-320)))
                    .isEqualTo(INF);
            assertThat(Geometry.timeUntilWallCollision(floor, new Circle(10, 18.75, 0.25), new Vect(1e-320, 1e-320)))
                    .isEqualTo(INF);
        }

        @Test
        void zeroVelocityZeroRadiusAndZeroSpinGiveDefinedAnswers() {
            Circle point = new Circle(3, 3, 0);
            assertThat(Geometry.timeUntilWallCollision(FLIPPER, point, Vect.ZERO)).isEqualTo(INF);
            assertThat(Geometry.timeUntilCircleCollision(new Circle(0, 0, 0), point, Vect.ZERO)).isEqualTo(INF);
            assertThat(Geometry.timeUntilBallBallCollision(point, Vect.ZERO, new Circle(0, 0, 0), Vect.ZERO))
                    .isEqualTo(INF);
            assertThat(Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 0, point, Vect.ZERO)).isEqualTo(INF);
            assertThat(Geometry.timeUntilRotatingCircleCollision(new Circle(0, 0, 0), Vect.ZERO, 0, point, Vect.ZERO))
                    .isEqualTo(INF);
            assertThat(Geometry.timeUntilCircleCollision(new Circle(0, 0, 0), new Vect(1, 0), new Vect(-1, 0)))
                    .isEqualTo(new Geometry.DoublePair(1));
            assertThat(Geometry.timeUntilCircleCollision(new Circle(0, 0, 0), new Vect(1, 0), new Vect(0, 1)))
                    .isEqualTo(Geometry.DOUBLE_PAIR_NAN);
            assertThat(Vect.ZERO.unitSize()).isEqualTo(Vect.ZERO);
        }

        @ParameterizedTest(name = "seed {0}")
        @MethodSource("physics.PitfallTest#seeds")
        void noTimeIsEverNaN(long seed) {
            RandomScene r = new RandomScene(seed);
            Vect pivot = r.coin() ? Vect.ZERO : r.point(2);
            Circle ball = new Circle(r.coin() ? pivot : r.point(3), r.coin() ? 0 : r.between(0, 1));
            Vect v = r.coin() ? Vect.ZERO : r.vector(0, 10);
            double w = r.coin() ? 0 : r.between(-20, 20);
            Circle circle = new Circle(r.coin() ? pivot : r.point(3), r.coin() ? 0 : r.between(0, 1));
            assertThat(Geometry.timeUntilWallCollision(FLIPPER, ball, v)).as("seed %d", seed).isNotNaN();
            assertThat(Geometry.timeUntilCircleCollision(circle, ball, v)).as("seed %d", seed).isNotNaN();
            assertThat(Geometry.timeUntilBallBallCollision(circle, v, ball, Vect.ZERO)).as("seed %d", seed).isNotNaN();
            assertThat(Geometry.timeUntilRotatingWallCollision(FLIPPER, pivot, w, ball, v)).as("seed %d", seed)
                    .isNotNaN();
            assertThat(Geometry.timeUntilRotatingCircleCollision(circle, pivot, w, ball, v)).as("seed %d", seed)
                    .isNotNaN();
        }
    }

    @Nested
    class Pitfall09ReflectOffARotatingSegmentAtItsEnd {
        @Test
        void beyondAnEndTheVelocityComesBackUnchanged() {
            // Ball touching the tip (2, 0) from beyond it: the foot of the perpendicular is 0.3 L off the segment.
            Vect v = new Vect(1, -2);
            for (Circle ball : new Circle[] {new Circle(2.3, 0.4, 0.5), new Circle(2 + 1e-5, 0.5, 0.5),
                    new Circle(-1e-5, 0.5, 0.5), new Circle(-3, 7, 0.5)}) {
                assertThat(Geometry.reflectRotatingWall(FLIPPER, Vect.ZERO, FLIPPER_SPEED, ball, v)).as("%s", ball)
                        .isEqualTo(v);
            }
        }

        @Test
        void aBallOffTheFaceIsReflectedAtTheFootOfThePerpendicular() {
            // The surface at (1, 0) moves at w x (1, 0) = (0, 1): a ball at rest 0.1 L clear leaves at (0, 2).
            Vect out = Geometry.reflectRotatingWall(FLIPPER, Vect.ZERO, 1, new Circle(1, 0.6, 0.5), Vect.ZERO);
            assertThat(out.x()).isCloseTo(0, within(1e-12));
            assertThat(out.y()).isCloseTo(2, within(1e-12));
        }

        @Test
        void aFaceContactAtOrWithinRoundingOfAnEndIsReflectedOffTheFace() {
            // The surface at (x, 0) moves at 1 x (x, 0) = (0, x), so a ball at rest leaves at (0, 2x).
            for (double x : new double[] {2, 2 - 5e-10, 2 + 5e-10, 0, -5e-10, 2 - 1e-6}) {
                Vect out = Geometry.reflectRotatingWall(FLIPPER, Vect.ZERO, 1, new Circle(x, 0.5, 0.5), Vect.ZERO);
                assertThat(out.x()).as("x = %s", x).isCloseTo(0, within(1e-12));
                assertThat(out.y()).as("x = %s", x).isCloseTo(2 * x, within(1e-12));
            }
        }

        @Test
        void theCircleMethodHandlesTheEndContactAndChangesTheVelocity() {
            // Tip moving at w x (2, 0) = (0, 2w); the ball at (2.3, 0.4) touches it along (0.6, 0.8).
            Circle atTip = new Circle(2.3, 0.4, 0.5);
            double w = 1;
            Vect out = Geometry.reflectRotatingCircle(new Circle(2, 0, 0), Vect.ZERO, w, atTip, Vect.ZERO);
            // relative (0, -2) has normal part -1.6 (0.6, 0.8); reflected: (0, -2) + 3.2 (0.6, 0.8), plus (0, 2).
            assertThat(out.x()).isCloseTo(1.92, within(1e-12));
            assertThat(out.y()).isCloseTo(2.56, within(1e-12));
        }

        @Test
        void atAngularVelocityZeroItIsReflectWall() {
            Circle farOff = new Circle(7, 3, 0.5);
            Vect v = new Vect(0.3, -2);
            assertThat(Geometry.reflectRotatingWall(FLIPPER, Vect.ZERO, 0, farOff, v, 0.9))
                    .isEqualTo(Geometry.reflectWall(FLIPPER, v, 0.9));
        }
    }

    @Nested
    class Pitfall10GlobalSettings {
        @Test
        void instancesWithDifferentForesightDoNotInterfere() {
            Circle ball = new Circle(1, 1.5, 0.5);
            GeometryImpl shortSight = new GeometryImpl(0.01, 4);
            GeometryImpl longSight = new GeometryImpl(5, 64);
            double t = longSight.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 1, ball, Vect.ZERO);
            assertThat(shortSight.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 1, ball, Vect.ZERO))
                    .isEqualTo(INF);
            assertThat(longSight.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 1, ball, Vect.ZERO))
                    .isEqualTo(t);
            double angle = Math.acos(0.5 / Math.sqrt(3.25)) - Math.atan2(2, 3);
            assertThat(t).isCloseTo(angle, within(1e-9));
        }

        @Test
        void theSlicesTuneSpeedNotAnswers() {
            Circle ball = new Circle(1, 1.5, 0.5);
            Vect v = new Vect(-0.4, 0.3);
            double coarse = new GeometryImpl(1, 1).timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 1.2, ball, v);
            double fine = new GeometryImpl(1, 100).timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 1.2, ball, v);
            assertThat(coarse).isFinite().isCloseTo(fine, within(1e-9));
        }

        @Test
        void theFacadeDefaultIsAFreshDefaultInstanceAndTuningItIsUndone() {
            Circle ball = new Circle(1, 1.5, 0.5);
            double viaDefault = new GeometryImpl().timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 1, ball,
                    Vect.ZERO);
            assertThat(Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 1, ball, Vect.ZERO))
                    .isEqualTo(viaDefault);
            try {
                Geometry.setForesight(0.01);
                assertThat(Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 1, ball, Vect.ZERO))
                        .isEqualTo(INF);
                Geometry.setTuningParameters(0.01, true, 8);
                assertThat(Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 1, ball, Vect.ZERO))
                        .isEqualTo(INF);
            } finally {
                Geometry.setGeometry(new GeometryImpl());
            }
            assertThat(Geometry.timeUntilRotatingWallCollision(FLIPPER, Vect.ZERO, 1, ball, Vect.ZERO))
                    .isEqualTo(viaDefault);
            assertThatThrownBy(() -> Geometry.setGeometry(null)).isInstanceOf(IllegalArgumentException.class);
        }
    }
}
