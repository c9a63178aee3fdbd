package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import physics.Circle;
import physics.Geometry;
import physics.Vect;

/**
 * {@link BallMeeting} gives the very double of {@code Geometry.timeUntilBallBallCollision} for two balls' circles, the
 * oracle: on random pairs touching, overlapping, grazing or apart at any scale, at rest or moving any way, and with
 * tiny, huge, infinite or NaN components ({@link OddVects}).
 */
class BallMeetingTest {
    private static final double R = Arena.BALL_RADIUS;

    @Test
    void itGivesTheApisTimeToTheBit() {
        SplittableRandom random = new SplittableRandom(4102);
        int met = 0;
        int atOnce = 0;
        for (int i = 0; i < 500_000; i++) {
            Vect c1 = OddVects.vect(random);
            Vect c2 = random.nextInt(4) == 0 ? near(c1, random) : OddVects.vect(random);
            Vect v1 = OddVects.vect(random);
            Vect v2 = random.nextInt(4) == 0 ? Vect.ZERO : OddVects.vect(random);

            double time = BallMeeting.time(c1.x() - c2.x(), c1.y() - c2.y(), v1.x() - v2.x(), v1.y() - v2.y());

            double api = Geometry.timeUntilBallBallCollision(new Circle(c1, R), v1, new Circle(c2, R), v2);
            assertThat(Double.doubleToLongBits(time)).as("case %d: %s %s, %s %s: %s, the API %s", i, c1, v1, c2, v2,
                    time, api).isEqualTo(Double.doubleToLongBits(api));
            if (time > 0 && time < Double.POSITIVE_INFINITY) {
                met++;
            } else if (time == 0) {
                atOnce++;
            }
        }
        assertThat(met).as("pairs that meet later").isGreaterThan(10_000);
        assertThat(atOnce).as("pairs touching or overlapping that close").isGreaterThan(10_000);
    }

    /** A centre within a few radii of c: touching, overlapping or just apart. */
    private static Vect near(Vect c, SplittableRandom random) {
        double angle = random.nextDouble(0, 2 * Math.PI);
        double distance = random.nextInt(3) == 0 ? 2 * R + random.nextDouble(-1e-9, 1e-9) : random.nextDouble(0, 3);
        return new Vect(c.x() + distance * Math.cos(angle), c.y() + distance * Math.sin(angle));
    }
}
