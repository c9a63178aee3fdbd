package physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import physics.Geometry.DoublePair;
import physics.Geometry.VectPair;

/** Hand-computed cases for every static (non-rotating) method, through the Geometry facade. */
class StaticGeometryTest {
    private static final double EPS = 1e-12;
    private static final double INF = Double.POSITIVE_INFINITY;

    private static void assertVect(Vect actual, double x, double y) {
        assertThat(actual.x()).as("x of %s", actual).isCloseTo(x, within(EPS));
        assertThat(actual.y()).as("y of %s", actual).isCloseTo(y, within(EPS));
    }

    @Nested
    class QuadraticSolution {
        @Test
        void twoRootsSmallerFirst() {
            assertThat(Geometry.quadraticSolution(1, -3, 2)).isEqualTo(new DoublePair(1, 2));
            assertThat(Geometry.quadraticSolution(-1, 3, -2)).isEqualTo(new DoublePair(1, 2));
        }

        @Test
        void doubleRootNoRootAndLinear() {
            assertThat(Geometry.quadraticSolution(1, -2, 1)).isEqualTo(new DoublePair(1));
            assertThat(Geometry.quadraticSolution(1, 0, 1)).isEqualTo(Geometry.DOUBLE_PAIR_NAN);
            assertThat(Geometry.quadraticSolution(0, 2, -4)).isEqualTo(new DoublePair(2));
            assertThat(Geometry.quadraticSolution(0, 0, 1)).isEqualTo(Geometry.DOUBLE_PAIR_NAN);
            assertThat(Geometry.quadraticSolution(1, 0, 0)).isEqualTo(new DoublePair(0));
        }

        @Test
        void smallRootKeepsItsDigits() {
            // x^2 - 1e8 x + 1: roots 1e8 and 1/1e8 (to 1e-16 relative); the naive formula gives 0 or 7.45e-9.
            DoublePair roots = Geometry.quadraticSolution(1, -1e8, 1);
            assertThat(roots.d1).isCloseTo(1e-8, within(1e-22));
            assertThat(roots.d2).isCloseTo(1e8, within(1e-6));
        }

        @Test
        void everyNumberIsARootHasNoParticularRoot() {
            assertThat(Geometry.quadraticSolution(0, 0, 0)).isEqualTo(Geometry.DOUBLE_PAIR_NAN);
        }

        @Test
        void minQuadraticSolution() {
            assertThat(Geometry.minQuadraticSolution(1, 0, -1)).isEqualTo(-1);
            assertThat(Geometry.minQuadraticSolution(1, 0, 1)).isNaN();
        }
    }

    @Nested
    class PerpendicularPoint {
        private final LineSegment floor = new LineSegment(0, 0, 4, 0);

        @Test
        void footOnTheSegment() {
            assertThat(Geometry.perpendicularPoint(floor, new Vect(1, 3))).isEqualTo(new Vect(1, 0));
            assertThat(Geometry.perpendicularPoint(floor, new Vect(1, -3))).isEqualTo(new Vect(1, 0));
        }

        @Test
        void bothEndsBelongToTheClosedSegment() {
            assertThat(Geometry.perpendicularPoint(floor, new Vect(4, 2))).isEqualTo(new Vect(4, 0));
            assertThat(Geometry.perpendicularPoint(floor, new Vect(0, 5))).isEqualTo(new Vect(0, 0));
        }

        @Test
        void footOffTheSegmentIsNullButOnTheWholeLine() {
            assertThat(Geometry.perpendicularPoint(floor, new Vect(5, 1))).isNull();
            assertThat(Geometry.perpendicularPointWholeLine(floor, new Vect(5, 1))).isEqualTo(new Vect(5, 0));
            assertVect(Geometry.perpendicularPointWholeLine(new LineSegment(0, 0, 1, 1), new Vect(2, 0)), 1, 1);
        }
    }

    @Nested
    class ApplyReflectionCoeff {
        @Test
        void scalesTheReflectedNormalPartOnly() {
            Vect incident = new Vect(1, -2);
            Vect reflected = new Vect(1, 2);
            assertVect(Geometry.applyReflectionCoeff(incident, reflected, 0.5), 1, 1);
            assertVect(Geometry.applyReflectionCoeff(incident, reflected, 1), 1, 2);
            assertVect(Geometry.applyReflectionCoeff(incident, reflected, 0), 1, 0);
        }
    }

    @Nested
    class TimeUntilWallCollision {
        private final LineSegment wall = new LineSegment(0, 10, 20, 10);

        private double time(double x, double y, double vx, double vy) {
            return Geometry.timeUntilWallCollision(wall, new Circle(x, y, 0.5), new Vect(vx, vy));
        }

        @Test
        void headOnFromEitherSide() {
            assertThat(time(5, 5, 0, 2)).isCloseTo(2.25, within(EPS));
            assertThat(time(5, 15, 0, -2)).isCloseTo(2.25, within(EPS));
        }

        @Test
        void glancingHitsOnlyIfTheTouchingPointIsOnTheSegment() {
            assertThat(time(5, 5, 3, 1)).isCloseTo(4.5, within(EPS)); // touches at x = 18.5
            assertThat(time(5, 5, 4, 1)).isEqualTo(INF); // would touch the line at x = 23
        }

        @Test
        void movingAwayParallelOrAtRestNever() {
            assertThat(time(5, 5, 0, -1)).isEqualTo(INF);
            assertThat(time(5, 5, 1, 0)).isEqualTo(INF);
            assertThat(time(5, 5, 0, 0)).isEqualTo(INF);
        }

        @Test
        void touchingOrOverlappingAndClosingIsNow() {
            assertThat(time(5, 9.5, 0, 1)).isZero();
            assertThat(time(5, 9.8, 0.3, 1)).isZero();
            assertThat(time(5, 10.5, 0, -1)).isZero();
        }

        @Test
        void touchingAndSeparatingIsNever() {
            assertThat(time(5, 9.5, 0, -1)).isEqualTo(INF);
            assertThat(time(5, 9.5, 1, 0)).isEqualTo(INF);
        }

        @Test
        void contactExactlyAtP1IsTheFacesAndAtP2IsNot() {
            assertThat(time(0, 5, 0, 1)).isCloseTo(4.5, within(EPS));
            assertThat(time(20, 5, 0, 1)).isEqualTo(INF);
        }

        @Test
        void slantedWall() {
            // Wall x + y = 10 (normal (1,1)/sqrt2); ball centre at the origin, radius 0.5, speed (1,1):
            // distance to the line 10/sqrt2, closing speed sqrt2 -> t = (10/sqrt2 - 0.5)/sqrt2 = 5 - 0.25 sqrt2.
            double t = Geometry.timeUntilWallCollision(new LineSegment(10, 0, 0, 10), new Circle(0, 0, 0.5),
                    new Vect(1, 1));
            assertThat(t).isCloseTo(5 - 0.25 * Math.sqrt(2), within(EPS));
        }
    }

    @Nested
    class ReflectWall {
        @Test
        void flipsTheNormalPart() {
            LineSegment floor = new LineSegment(0, 0, 5, 0);
            assertVect(Geometry.reflectWall(floor, new Vect(1, 2)), 1, -2);
            assertVect(Geometry.reflectWall(floor, new Vect(1, 2), 0.5), 1, -1);
            assertVect(Geometry.reflectWall(new LineSegment(0, 0, 1, 1), new Vect(1, 0)), 0, 1);
        }
    }

    @Nested
    class DistanceSquared {
        @Test
        void bothForms() {
            assertThat(Geometry.distanceSquared(new Vect(1, 1), new Vect(4, 5))).isEqualTo(25);
            assertThat(Geometry.distanceSquared(1, 1, 4, 5)).isEqualTo(25);
        }
    }

    @Nested
    class TimeUntilCircleCollision {
        private final Circle bumper = new Circle(0, 0, 1);

        private double time(Circle target, double x, double y, double vx, double vy) {
            return Geometry.timeUntilCircleCollision(target, new Circle(x, y, 0.5), new Vect(vx, vy));
        }

        @Test
        void headOn() {
            assertThat(time(bumper, 10, 0, -1, 0)).isCloseTo(8.5, within(EPS));
        }

        @Test
        void glancing() {
            // centre line y = 1.2: touches when x^2 + 1.44 = 1.5^2, x = 0.9, after 9.1 s.
            assertThat(time(bumper, 10, 1.2, -1, 0)).isCloseTo(9.1, within(EPS));
            assertThat(time(bumper, 10, 2, -1, 0)).isEqualTo(INF);
        }

        @Test
        void cornerIsAZeroRadiusCircle() {
            assertThat(time(new Circle(0, 0, 0), 3, 4, -0.6, -0.8)).isCloseTo(4.5, within(EPS));
        }

        @Test
        void movingAwayOrAtRestNever() {
            assertThat(time(bumper, 10, 0, 1, 0)).isEqualTo(INF);
            assertThat(time(bumper, 10, 0, 0, 0)).isEqualTo(INF);
        }

        @Test
        void touchingClosingNowTouchingSeparatingNever() {
            assertThat(time(bumper, 1.5, 0, -1, 0)).isZero();
            assertThat(time(bumper, 1.4, 0, -1, 3)).isZero();
            assertThat(time(bumper, 1.5, 0, 1, 0)).isEqualTo(INF);
            assertThat(time(bumper, 1.5, 0, 0, 1)).isEqualTo(INF);
        }
    }

    @Nested
    class PointCircleTimes {
        private final Circle unit = new Circle(0, 0, 1);

        @Test
        void entryAndExit() {
            assertThat(Geometry.timeUntilCircleCollision(unit, new Vect(-5, 0), new Vect(1, 0)))
                    .isEqualTo(new DoublePair(4, 6));
            assertThat(Geometry.timeUntilCircleCollision(unit, Vect.ZERO, new Vect(2, 0)))
                    .isEqualTo(new DoublePair(-0.5, 0.5));
        }

        @Test
        void grazeMissAndRest() {
            DoublePair graze = Geometry.timeUntilCircleCollision(unit, new Vect(-5, 1), new Vect(1, 0));
            assertThat(graze.d1).isCloseTo(5, within(EPS));
            assertThat(graze.d2).isCloseTo(5, within(EPS));
            assertThat(Geometry.timeUntilCircleCollision(unit, new Vect(-5, 2), new Vect(1, 0)))
                    .isEqualTo(Geometry.DOUBLE_PAIR_NAN);
            assertThat(Geometry.timeUntilCircleCollision(unit, new Vect(-5, 0), Vect.ZERO))
                    .isEqualTo(Geometry.DOUBLE_PAIR_NAN);
            assertThat(Geometry.DOUBLE_PAIR_NAN.areFinite()).isFalse();
        }
    }

    @Nested
    class ReflectCircle {
        @Test
        void flipsThePartAlongTheLineOfCentres() {
            assertVect(Geometry.reflectCircle(Vect.ZERO, new Vect(1, 0), new Vect(-2, 3)), 2, 3);
            assertVect(Geometry.reflectCircle(Vect.ZERO, new Vect(1, 0), new Vect(-2, 3), 0.5), 1, 3);
            assertVect(Geometry.reflectCircle(new Vect(1, 1), new Vect(2, 2), new Vect(-1, 0)), 0, 1);
        }

        @Test
        void coincidentCentresLeaveTheVelocityUnchanged() {
            assertThat(Geometry.reflectCircle(Vect.ZERO, Vect.ZERO, Vect.X_HAT)).isEqualTo(Vect.X_HAT);
        }
    }

    @Nested
    class RotateAround {
        @Test
        void pointSegmentAndCircleTurnPlusXTowardPlusY() {
            Vect pivot = new Vect(1, 1);
            assertVect(Geometry.rotateAround(new Vect(2, 1), pivot, Angle.DEG_90), 1, 2);
            LineSegment s = Geometry.rotateAround(new LineSegment(1, 1, 3, 1), pivot, Angle.DEG_180);
            assertVect(s.p1(), 1, 1);
            assertVect(s.p2(), -1, 1);
            Circle c = Geometry.rotateAround(new Circle(2, 1, 0.25), pivot, Angle.DEG_270);
            assertVect(c.getCenter(), 1, 0);
            assertThat(c.getRadius()).isEqualTo(0.25);
        }
    }

    @Nested
    class TimeUntilBallBallCollision {
        @Test
        void headOnSameVelocitySeparatingTouching() {
            Circle a = new Circle(0, 0, 0.5);
            assertThat(Geometry.timeUntilBallBallCollision(a, new Vect(1, 0), new Circle(10, 0, 0.5), new Vect(-1, 0)))
                    .isCloseTo(4.5, within(EPS));
            assertThat(Geometry.timeUntilBallBallCollision(a, new Vect(1, 0), new Circle(10, 0, 0.5), new Vect(1, 0)))
                    .isEqualTo(INF);
            assertThat(Geometry.timeUntilBallBallCollision(a, new Vect(-1, 0), new Circle(10, 0, 0.5), Vect.ZERO))
                    .isEqualTo(INF);
            assertThat(Geometry.timeUntilBallBallCollision(a, new Vect(1, 0), new Circle(1, 0, 0.5), Vect.ZERO))
                    .isZero();
            assertThat(Geometry.timeUntilBallBallCollision(a, Vect.ZERO, new Circle(1, 0, 0.5), new Vect(1, 0)))
                    .isEqualTo(INF);
        }

        @Test
        void glancingAndMiss() {
            // relative motion along y = 0.6, sum of radii 1: touches at x = 0.8, i.e. after (10 - 0.8) / 2 s.
            Circle a = new Circle(0, 0, 0.5);
            assertThat(Geometry.timeUntilBallBallCollision(a, new Vect(1, 0), new Circle(10, 0.6, 0.5), new Vect(-1, 0)))
                    .isCloseTo(4.6, within(EPS));
            assertThat(Geometry.timeUntilBallBallCollision(a, new Vect(1, 0), new Circle(10, 1.1, 0.5), new Vect(-1, 0)))
                    .isEqualTo(INF);
        }
    }

    @Nested
    class ReflectBalls {
        @Test
        void equalMassesExchangeNormalParts() {
            VectPair out = Geometry.reflectBalls(Vect.ZERO, 1, new Vect(1, 2), new Vect(1, 0), 1, new Vect(-1, 0));
            assertVect(out.v1, -1, 2);
            assertVect(out.v2, 1, 0);
        }

        @Test
        void unequalMasses() {
            // 1-D elastic: u1' = (m1 - m2) u1 / (m1 + m2) = -2, u2' = 2 m1 u1 / (m1 + m2) = 2.
            VectPair out = Geometry.reflectBalls(Vect.ZERO, 1, new Vect(4, 0), new Vect(1, 0), 3, Vect.ZERO);
            assertVect(out.v1, -2, 0);
            assertVect(out.v2, 2, 0);
        }

        @Test
        void infiniteMassIsAnImmovableBall() {
            VectPair out = Geometry.reflectBalls(Vect.ZERO, 1, new Vect(1, 1), new Vect(1, 0), INF, Vect.ZERO);
            assertVect(out.v1, -1, 1);
            assertVect(out.v2, 0, 0);
            VectPair swapped = Geometry.reflectBalls(Vect.ZERO, INF, Vect.ZERO, new Vect(1, 0), 1, new Vect(-1, 1));
            assertVect(swapped.v1, 0, 0);
            assertVect(swapped.v2, 1, 1);
        }

        @Test
        void undefinedMassRatiosAndCoincidentCentresLeaveTheVelocitiesUnchanged() {
            Geometry.VectPair unchanged = new Geometry.VectPair(Vect.X_HAT, Vect.ZERO);
            assertThat(Geometry.reflectBalls(Vect.ZERO, 0, Vect.X_HAT, Vect.Y_HAT, 0, Vect.ZERO)).isEqualTo(unchanged);
            assertThat(Geometry.reflectBalls(Vect.ZERO, INF, Vect.X_HAT, Vect.Y_HAT, INF, Vect.ZERO))
                    .isEqualTo(unchanged);
            assertThat(Geometry.reflectBalls(Vect.ZERO, 1, Vect.X_HAT, Vect.ZERO, 1, Vect.ZERO)).isEqualTo(unchanged);
            // A massless first ball is turned back as off a wall: 2 m2 / (m1 + m2) = 2.
            assertThat(Geometry.reflectBalls(Vect.ZERO, 0, Vect.Y_HAT, Vect.Y_HAT, 1, Vect.ZERO).v1)
                    .isEqualTo(new Vect(0, -1));
        }
    }

    @Nested
    class Pairs {
        @Test
        void equalityAndHashCode() {
            assertThat(new DoublePair(1, 2)).isEqualTo(new DoublePair(1, 2)).hasSameHashCodeAs(new DoublePair(1, 2));
            assertThat(new DoublePair(-0.0)).isEqualTo(new DoublePair(0.0)).hasSameHashCodeAs(new DoublePair(0.0));
            assertThat(new DoublePair(Double.NaN)).isEqualTo(Geometry.DOUBLE_PAIR_NAN);
            assertThat(new DoublePair(1, 2).areFinite()).isTrue();
            assertThat(new DoublePair(1, INF).areFinite()).isFalse();
            VectPair p = new VectPair(Vect.X_HAT, Vect.Y_HAT);
            assertThat(p).isEqualTo(new VectPair(new Vect(1, 0), new Vect(0, 1))).hasSameHashCodeAs(
                    new VectPair(new Vect(1, 0), new Vect(0, 1)));
            assertThat(p).isNotEqualTo(new VectPair(Vect.Y_HAT, Vect.X_HAT));
            assertThat(p.toString()).contains("<1.0,0.0>");
            assertThat(new DoublePair(1, 2).toString()).contains("1.0", "2.0");
        }
    }
}
