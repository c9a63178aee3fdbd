package physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

/** Hand-computed cases for the rotating methods, through the Geometry facade (foresight 1 s). */
class RotatingGeometryTest {
    private static final double INF = Double.POSITIVE_INFINITY;
    /** The reported contact is at most 1e-10 L before the true one; in time that is well under 1e-9 s here. */
    private static final double TIME = 1e-9;
    private static final double QUARTER_TURN_PER_SECOND = Math.PI / 2;
    private final LineSegment flipper = new LineSegment(0, 0, 2, 0);

    private static void assertVect(Vect actual, double x, double y) {
        assertThat(actual.x()).as("x of %s", actual).isCloseTo(x, within(1e-12));
        assertThat(actual.y()).as("y of %s", actual).isCloseTo(y, within(1e-12));
    }

    @Nested
    class TimeUntilRotatingWallCollision {
        @Test
        void segmentTurningIntoABallAtRest() {
            // Distance from (1, 1.5) to the line at angle a: 1.5 cos a - sin a = sqrt(3.25) cos(a + atan(2/3)) = 0.5.
            double angle = Math.acos(0.5 / Math.sqrt(3.25)) - Math.atan2(2, 3);
            double t = Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, QUARTER_TURN_PER_SECOND,
                    new Circle(1, 1.5, 0.5), Vect.ZERO);
            assertThat(t).isCloseTo(angle / QUARTER_TURN_PER_SECOND, within(TIME));
        }

        @Test
        void bothRotationDirectionsMirrorEachOther() {
            double angle = Math.acos(0.5 / Math.sqrt(3.25)) - Math.atan2(2, 3);
            double t = Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, -QUARTER_TURN_PER_SECOND,
                    new Circle(1, -1.5, 0.5), Vect.ZERO);
            assertThat(t).isCloseTo(angle / QUARTER_TURN_PER_SECOND, within(TIME));
            assertThat(Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, -QUARTER_TURN_PER_SECOND,
                    new Circle(1, 1.5, 0.5), Vect.ZERO)).as("turning away for a quarter turn").isEqualTo(INF);
        }

        @Test
        void zeroAngularVelocityIsTheStaticWall() {
            double t = Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, 0, new Circle(1, 1.5, 0.5),
                    new Vect(0, -2));
            assertThat(t).isCloseTo(0.5, within(TIME));
            assertThat(Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, 0, new Circle(1, 3, 0.5),
                    new Vect(0, 1))).as("moving away").isEqualTo(INF);
            assertThat(Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, 0, new Circle(1, 3, 0.5),
                    Vect.ZERO)).as("all at rest").isEqualTo(INF);
            assertThat(Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, 0, new Circle(1, 3, 0.5),
                    new Vect(1, 0))).as("parallel").isEqualTo(INF);
        }

        @Test
        void glancingBlowFromAMovingBall() {
            // Still segment, ball falling on x = 2.3, beyond the end: it touches the end (2, 0) when
            // 0.3^2 + y^2 = 0.5^2, at y = 0.4, after falling 2.6 L at 4 L/s. That is the end circle's contact;
            // the face is never touched (as for timeUntilWallCollision).
            Circle ball = new Circle(2.3, 3, 0.5);
            Vect down = new Vect(0, -4);
            assertThat(Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, 0, ball, down)).isEqualTo(INF);
            assertThat(Geometry.timeUntilRotatingCircleCollision(new Circle(2, 0, 0), Vect.ZERO, 0, ball, down))
                    .isCloseTo(0.65, within(TIME));
        }

        @Test
        void outOfReachNever() {
            assertThat(Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, 10, new Circle(10, 10, 0.5),
                    Vect.ZERO)).isEqualTo(INF);
        }

        @Test
        void touchingAndClosingIsNowTouchingAndSeparatingIsNever() {
            Circle resting = new Circle(1, 0.5, 0.5);
            assertThat(Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, 1, resting, Vect.ZERO)).isZero();
            assertThat(Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, -1, resting, Vect.ZERO))
                    .isEqualTo(INF);
        }

        @Test
        void touchingAndSeparatingFindsTheNextContactAfterAFullTurn() {
            // Turning back at pi rad/s from touching (1, 0.5), the segment comes round to it from above at the
            // angle a where 0.5 cos a - sin a = -0.5, i.e. a = 2 atan(1/2), after turning 2 pi - a.
            GeometryImpl twoSeconds = new GeometryImpl(2, GeometryImpl.DEFAULT_SEARCH_SLICES);
            double t = twoSeconds.timeUntilRotatingWallCollision(flipper, Vect.ZERO, -Math.PI, new Circle(1, 0.5, 0.5),
                    Vect.ZERO);
            assertThat(t).isCloseTo((2 * Math.PI - 2 * Math.atan(0.5)) / Math.PI, within(TIME));
        }

        @Test
        void contactAtTheTipIsFound() {
            // The tip (2 cos a, 2 sin a) reaches distance 0.5 from (2.2, 1) when cos(a - atan2(1, 2.2)) =
            // (5.84 + 4 - 0.25) / (4 sqrt(5.84)); the foot of the perpendicular is then off the segment.
            double angle = Math.atan2(1, 2.2) - Math.acos((5.84 + 4 - 0.25) / (4 * Math.sqrt(5.84)));
            Circle ball = new Circle(2.2, 1, 0.5);
            assertThat(Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, QUARTER_TURN_PER_SECOND, ball,
                    Vect.ZERO)).as("the face: the foot is off it").isEqualTo(INF);
            double t = Geometry.timeUntilRotatingCircleCollision(new Circle(2, 0, 0), Vect.ZERO,
                    QUARTER_TURN_PER_SECOND, ball, Vect.ZERO);
            assertThat(t).isCloseTo(angle / QUARTER_TURN_PER_SECOND, within(TIME));
        }

        @Test
        void aBallRunningInOverTheTipMeetsTheFaceOnlyWhenItComesDownOntoIt() {
            // Still segment; the ball moves along y = 0.3 (< its radius 0.5) from beyond the tip: it runs into the
            // tip, never onto the face (static: the same). Moving down from (1, 3) it meets the face at y = 0.5.
            assertThat(Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, 0, new Circle(4, 0.3, 0.5),
                    new Vect(-2, 0))).isEqualTo(INF);
            assertThat(Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, 1e-3, new Circle(4, 0.3, 0.5),
                    new Vect(-2, 0))).as("turning slowly").isEqualTo(INF);
            assertThat(Geometry.timeUntilRotatingWallCollision(flipper, Vect.ZERO, 0, new Circle(1, 3, 0.5),
                    new Vect(0, -5))).isCloseTo(0.5, within(TIME));
        }
    }

    @Nested
    class TimeUntilRotatingCircleCollision {
        @Test
        void circleSwingingIntoABallAtRest() {
            // Centres (2 cos a, 2 sin a) and (0, 2): distance^2 = 8 (1 - sin a) = 0.5^2.
            double angle = Math.asin(31.0 / 32);
            double t = Geometry.timeUntilRotatingCircleCollision(new Circle(2, 0, 0.25), Vect.ZERO,
                    QUARTER_TURN_PER_SECOND, new Circle(0, 2, 0.25), Vect.ZERO);
            assertThat(t).isCloseTo(angle / QUARTER_TURN_PER_SECOND, within(TIME));
            assertThat(Geometry.timeUntilRotatingCircleCollision(new Circle(2, 0, 0.25), Vect.ZERO,
                    -QUARTER_TURN_PER_SECOND, new Circle(0, 2, 0.25), Vect.ZERO)).isEqualTo(INF);
        }

        @Test
        void zeroAngularVelocityIsTheStaticCircle() {
            Circle bumper = new Circle(0, 0, 1);
            assertThat(Geometry.timeUntilRotatingCircleCollision(bumper, new Vect(5, 5), 0, new Circle(2, 0, 0.5),
                    new Vect(-2, 0))).isCloseTo(0.25, within(TIME));
        }

        @Test
        void circleAtThePivotOnlySpins() {
            Circle hub = new Circle(0, 0, 1);
            assertThat(Geometry.timeUntilRotatingCircleCollision(hub, Vect.ZERO, 20, new Circle(2, 0, 0.5),
                    Vect.ZERO)).isEqualTo(INF);
            assertThat(Geometry.timeUntilRotatingCircleCollision(hub, Vect.ZERO, 20, new Circle(2, 0, 0.5),
                    new Vect(-1, 0))).isCloseTo(0.5, within(TIME));
        }
    }

    @Nested
    class ReflectRotatingWall {
        @Test
        void flipperHitsABallAtRest() {
            // Contact (1, 0), surface velocity 2 x (1, 0) = (0, 2); relative (0, -2) reflects to (0, 2) -> (0, 4).
            Circle ball = new Circle(1, 0.5, 0.5);
            assertVect(Geometry.reflectRotatingWall(flipper, Vect.ZERO, 2, ball, Vect.ZERO), 0, 4);
            assertVect(Geometry.reflectRotatingWall(flipper, Vect.ZERO, 2, ball, Vect.ZERO, 0.5), 0, 3);
        }

        @Test
        void negativeAngularVelocityFromBelow() {
            Circle ball = new Circle(1, -0.5, 0.5);
            assertVect(Geometry.reflectRotatingWall(flipper, Vect.ZERO, -2, ball, new Vect(1, 0)), 1, -4);
        }

        @Test
        void zeroAngularVelocityIsReflectWall() {
            Circle ball = new Circle(1, 0.5, 0.5);
            assertVect(Geometry.reflectRotatingWall(flipper, Vect.ZERO, 0, ball, new Vect(3, -1)), 3, 1);
            assertVect(Geometry.reflectRotatingWall(flipper, Vect.ZERO, 0, ball, new Vect(3, -1), 0.5), 3, 0.5);
        }
    }

    @Nested
    class ReflectRotatingCircle {
        @Test
        void swingingCircleHitsABallAtRest() {
            // Contact (2, 0.25), surface velocity 1 x (2, 0.25) = (-0.25, 2); relative (0.25, -2) -> (0.25, 2).
            Circle tip = new Circle(2, 0, 0.25);
            Circle ball = new Circle(2, 0.5, 0.25);
            assertVect(Geometry.reflectRotatingCircle(tip, Vect.ZERO, 1, ball, Vect.ZERO), 0, 4);
            assertVect(Geometry.reflectRotatingCircle(tip, Vect.ZERO, 1, ball, Vect.ZERO, 0), 0, 2);
        }

        @Test
        void zeroAngularVelocityIsReflectCircle() {
            Circle bumper = new Circle(0, 0, 1);
            Circle ball = new Circle(1.5, 0, 0.5);
            assertVect(Geometry.reflectRotatingCircle(bumper, new Vect(3, 3), 0, ball, new Vect(-2, 1)), 2, 1);
        }
    }
}
