package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import physics.Geometry;
import physics.Vect;

/**
 * {@link BallBounce} gives the very doubles of {@code Geometry.reflectBalls} with masses 1 and 1, the oracle: on
 * random balls touching or apart at any scale, at rest or moving any way, centres coinciding or a tiny offset apart,
 * and infinite or NaN components ({@link OddVects}).
 */
class BallBounceTest {
    @Test
    void itGivesTheApisVelocitiesToTheBit() {
        SplittableRandom random = new SplittableRandom(4101);
        BallBounce bounce = new BallBounce();
        int changed = 0;
        for (int i = 0; i < 500_000; i++) {
            Vect c1 = OddVects.vect(random);
            Vect c2 = random.nextInt(8) == 0 ? c1 : random.nextInt(8) == 0
                    ? new Vect(c1.x() + Math.ulp(c1.x()), c1.y()) : OddVects.vect(random);
            Vect v1 = OddVects.vect(random);
            Vect v2 = OddVects.vect(random);

            bounce.between(c1.x(), c1.y(), v1.x(), v1.y(), c2.x(), c2.y(), v2.x(), v2.y());

            Geometry.VectPair api = Geometry.reflectBalls(c1, 1, v1, c2, 1, v2);
            String as = String.format("case %d: %s %s, %s %s", i, c1, v1, c2, v2);
            assertThat(bits(bounce.firstX)).as(as).isEqualTo(bits(api.v1.x()));
            assertThat(bits(bounce.firstY)).as(as).isEqualTo(bits(api.v1.y()));
            assertThat(bits(bounce.secondX)).as(as).isEqualTo(bits(api.v2.x()));
            assertThat(bits(bounce.secondY)).as(as).isEqualTo(bits(api.v2.y()));
            if (!api.v1.equals(v1)) {
                changed++;
            }
        }
        assertThat(changed).as("bounces that change the velocities").isGreaterThan(300_000);
    }

    private static long bits(double value) {
        return Double.doubleToRawLongBits(value);
    }
}
