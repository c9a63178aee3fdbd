package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;

import org.junit.jupiter.api.Test;

import physics.Vect;

/**
 * A ball that only loses energy in a tick ends it with no more shadow energy than it began with (docs/design.md,
 * "Energy drift"). A bounce at a fraction s of the tick moves S (|u|^2/2 - g . p, u the velocity half a kick from
 * the tick's) by (s - 1/2) dt g . dv on top of what the bounce itself takes: early in a tick, off a floor, that is more than a coefficient of 0.99 takes,
 * and the ball would bounce higher than it fell from.
 */
class LossCapTest {
    private static final Vect GRAVITY = new Vect(0, 25);
    private static final double DT = 1.0 / 60;
    private static final double FALL = 5;
    /** The bounce's share of the tick and its coefficient: a timing gain above the loss. */
    private static final double AT = 0.1;
    private static final double COEFFICIENT = 0.99;

    @Test
    void aLossyBounceEarlyInATickEndsWithTheShadowEnergyItBeganWith() {
        ShadowEnergy energy = new ShadowEnergy(LoopSettings.STANDARD);
        Ball ball = fallingBall();
        energy.begin(GRAVITY, DT, 1);
        energy.start(ball);
        double before = shadowAtStart(ball);
        bounceOffTheFloor(ball);
        energy.lost(ball);
        double gain = shadowAtEnd(ball) - before;
        // (s - 1/2) dt g . dv less the bounce's own loss, (1 - e^2) v^2 / 2
        double dv = -(1 + COEFFICIENT) * FALL;
        assertThat(gain).isCloseTo((AT - 0.5) * DT * GRAVITY.y() * dv - (1 - COEFFICIENT * COEFFICIENT) * FALL * FALL / 2,
                within(1e-9));
        assertThat(gain).isPositive();

        energy.restore(b -> List.of());

        assertThat(shadowAtEnd(ball)).isCloseTo(before, within(1e-9));
        assertThat(ball.vx()).isZero();
        assertThat(ball.vy()).isNegative().isGreaterThan(-COEFFICIENT * FALL);
    }

    @Test
    void aBallThatMayHaveGainedEnergyIsLeftAlone() {
        ShadowEnergy energy = new ShadowEnergy(LoopSettings.STANDARD);
        Ball ball = fallingBall();
        energy.begin(GRAVITY, DT, 1);
        energy.start(ball);
        bounceOffTheFloor(ball);
        energy.lost(ball);
        energy.mayGain(ball);   // a moving shape struck it, say
        double after = shadowAtEnd(ball);

        energy.restore(b -> List.of());

        assertThat(shadowAtEnd(ball)).isEqualTo(after);
    }

    private static Ball fallingBall() {
        return new Ball("B", new Vect(10, 10), new Vect(0, FALL));
    }

    /** The tick's motion: AT of it falling, the bounce off a floor below, the rest rising. */
    private static void bounceOffTheFloor(Ball ball) {
        ball.moveTo(new Vect(10, 10 + FALL * AT * DT));
        ball.setVelocity(new Vect(0, -COEFFICIENT * FALL));
        ball.moveTo(new Vect(10, ball.y() - COEFFICIENT * FALL * (1 - AT) * DT));
    }

    /** Right after stage 1's gravity kick: |v - g dt/2|^2/2 - g . p. */
    private static double shadowAtStart(Ball ball) {
        return shadow(ball, -1);
    }

    /** At the end of the tick, half a kick before the next: |v + g dt/2|^2/2 - g . p. */
    private static double shadowAtEnd(Ball ball) {
        return shadow(ball, 1);
    }

    private static double shadow(Ball ball, int halfKick) {
        double ux = ball.vx() + halfKick * GRAVITY.x() * DT / 2;
        double uy = ball.vy() + halfKick * GRAVITY.y() * DT / 2;
        return (ux * ux + uy * uy) / 2 - (GRAVITY.x() * ball.x() + GRAVITY.y() * ball.y());
    }
}
