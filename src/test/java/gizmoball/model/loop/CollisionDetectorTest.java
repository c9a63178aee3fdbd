package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import physics.Geometry;
import physics.LineSegment;
import physics.Vect;

/**
 * The detector's test of closing on a face, reckoned on the components (issue 39: no vector made per face asked),
 * answers what the Vect arithmetic it stands for answers, on random faces, balls, velocities and times, among them
 * faces along the axes, balls on the line and velocities that only graze.
 */
class CollisionDetectorTest {
    @Test
    void closingOnAFaceIsTheVectArithmeticsAnswer() {
        SplittableRandom random = new SplittableRandom(39);
        int closing = 0;
        for (int i = 0; i < 200_000; i++) {
            double x1 = coordinate(random);
            double y1 = coordinate(random);
            boolean axis = random.nextInt(3) == 0;
            double x2 = axis && random.nextBoolean() ? x1 : coordinate(random);
            double y2 = axis && x2 != x1 ? y1 : coordinate(random);
            LineSegment face = new LineSegment(x1, y1, x2, y2);
            Ball ball = new Ball("B", new Vect(coordinate(random), random.nextInt(10) == 0 ? y1 : coordinate(random)),
                    Vect.ZERO);
            Vect velocity = random.nextInt(10) == 0 ? new Vect(x2 - x1, y2 - y1)   // along the face: a graze
                    : new Vect(random.nextDouble(-100, 100), random.nextInt(8) == 0 ? 0 : random.nextDouble(-100, 100));
            double time = random.nextInt(10) == 0 ? 0 : random.nextDouble(0, 0.02);

            Vect centre = ball.position().plus(velocity.times(time));
            boolean expected = CollisionDetector.closing(
                    centre.minus(Geometry.perpendicularPointWholeLine(face, centre)), velocity);

            assertThat(CollisionDetector.closesOnSegment(face, ball, velocity, time)).as("case %d", i)
                    .isEqualTo(expected);
            closing += expected ? 1 : 0;
        }
        assertThat(closing).as("both answers are asked for").isBetween(20_000, 180_000);
    }

    /** A coordinate on the board, often a whole or half number as gizmos have them. */
    private static double coordinate(SplittableRandom random) {
        return random.nextInt(3) == 0 ? random.nextInt(41) / 2.0 : random.nextDouble(0, 20);
    }
}
