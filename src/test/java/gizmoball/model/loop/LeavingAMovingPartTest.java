package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.Random;
import java.util.stream.IntStream;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import physics.Vect;

/**
 * How fast a turning face closes on a ball moving in a straight line (docs/design.md, "Contact clusters", the rows):
 * {@link ContactCluster#gaining} against the second derivative of the distance itself, the ball moved on and the
 * face turned about its pivot, taken by central differences.
 */
class LeavingAMovingPartTest {
    /** Seconds: the step of the central differences. */
    private static final double H = 1e-4;

    record Scene(Vect pivot, double omega, Vect onFace, Vect normal, Vect centre, Vect velocity) {
        /** L: from the face, turned for t seconds, to the ball, moved on for t seconds. */
        double distance(double t) {
            double turn = omega * t;
            Vect n = new Vect(normal.x() * StrictMath.cos(turn) - normal.y() * StrictMath.sin(turn),
                    normal.x() * StrictMath.sin(turn) + normal.y() * StrictMath.cos(turn));
            // the face turns with the body: its offset from the pivot along its own normal stays what it was
            return centre.plus(velocity.times(t)).minus(pivot).dot(n) - onFace.minus(pivot).dot(normal);
        }
    }

    static Stream<Scene> scenes() {
        Random random = new Random(20_2612L);
        return IntStream.range(0, 300).mapToObj(i -> {
            Vect pivot = new Vect(20 * random.nextDouble(), 20 * random.nextDouble());
            double omega = 40 * (random.nextDouble() - 0.5);   // a flipper turns at 18.8 rad/s
            double angle = 2 * Math.PI * random.nextDouble();
            Vect normal = new Vect(Math.cos(angle), Math.sin(angle));
            Vect onFace = pivot.plus(new Vect(-normal.y(), normal.x()).times(4 * (random.nextDouble() - 0.5)))
                    .plus(normal.times(0.25 * random.nextDouble()));
            Vect centre = onFace.plus(normal.times(Arena.BALL_RADIUS));
            double heading = 2 * Math.PI * random.nextDouble();
            Vect velocity = new Vect(Math.cos(heading), Math.sin(heading)).times(100 * random.nextDouble());
            return new Scene(pivot, omega, onFace, normal, centre, velocity);
        });
    }

    @ParameterizedTest
    @MethodSource("scenes")
    void theFaceGainsOnTheBallAsTheSecondDerivativeOfTheDistanceSays(Scene scene) {
        double second = (scene.distance(H) - 2 * scene.distance(0) + scene.distance(-H)) / (H * H);
        double scale = scene.omega() * scene.omega() * scene.centre().minus(scene.pivot()).length()
                + 2 * Math.abs(scene.omega()) * scene.velocity().length();

        double gaining = ContactCluster.gaining(scene.pivot(), scene.omega(), scene.centre(), scene.normal(),
                scene.velocity());

        // Central differences err by H^2/12 times the fourth derivative, about omega^2 times the scale here.
        assertThat(gaining).isCloseTo(-second, within(1e-5 * scale + 1e-6));
    }

    @Test
    void aBallAtRestBeforeATurningFaceIsMetAtOmegaSquaredTimesItsDistanceFromThePivot() {
        Vect pivot = new Vect(10, 10);
        Vect normal = new Vect(0, -1);
        Vect centre = new Vect(11, 9.5);   // 0.5 from the pivot along the normal
        assertThat(ContactCluster.gaining(pivot, 3, centre, normal, Vect.ZERO)).isCloseTo(9 * 0.5, within(1e-12));
    }

    @Test
    void aBallSlidingOutAlongAFaceThatTurnsIntoItIsMetTwiceOmegaTimesItsSpeedFaster() {
        Vect pivot = new Vect(10, 10);
        Vect normal = new Vect(0, -1);   // the face's top side (-y is up)
        Vect onLine = new Vect(11, 10);
        Vect sliding = new Vect(40, 0);
        double omega = -3;   // +y toward +x: right of the pivot the face rises into the ball
        double atRest = ContactCluster.gaining(pivot, omega, onLine, normal, Vect.ZERO);
        assertThat(ContactCluster.gaining(pivot, omega, onLine, normal, sliding) - atRest)
                .isCloseTo(2 * 3 * 40, within(1e-9));
        assertThat(ContactCluster.gaining(pivot, -omega, onLine, normal, sliding) - atRest)
                .as("turning the other way, the face falls away from it").isCloseTo(-2 * 3 * 40, within(1e-9));
    }
}
