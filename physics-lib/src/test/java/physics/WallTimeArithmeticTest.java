package physics;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

/**
 * timeUntilWallCollision is reckoned on the components, making no vector (an engine asks it for every face in reach
 * of every ball, issue 39 of the game); it gives exactly the doubles of the Vect arithmetic it stands for, written out
 * here as it was, on random faces, balls and velocities: along the axes, slanted, of zero length, touching, inside,
 * parallel and at rest.
 */
class WallTimeArithmeticTest {
    @Test
    void theTimeIsTheVectArithmeticsToTheLastBit() {
        SplittableRandom random = new SplittableRandom(39);
        int finite = 0;
        for (int i = 0; i < 300_000; i++) {
            double x1 = coordinate(random);
            double y1 = coordinate(random);
            int kind = random.nextInt(6);
            double x2 = kind == 0 ? x1 : coordinate(random);
            double y2 = kind == 1 || kind == 2 && x2 != x1 ? y1 : coordinate(random);
            LineSegment line = new LineSegment(x1, y1, x2, y2);
            Circle ball = new Circle(coordinate(random), random.nextInt(8) == 0 ? y1 : coordinate(random),
                    random.nextInt(5) == 0 ? 0 : 0.25);
            Vect velocity = kind == 3 ? new Vect(x2 - x1, y2 - y1) : kind == 4 && random.nextBoolean() ? Vect.ZERO
                    : new Vect(random.nextDouble(-100, 100), random.nextInt(8) == 0 ? 0 : random.nextDouble(-100, 100));

            double time = Geometry.timeUntilWallCollision(line, ball, velocity);

            assertThat(Double.doubleToRawLongBits(time)).as("case %d: %s %s %s", i, line, ball, velocity)
                    .isEqualTo(Double.doubleToRawLongBits(withVectors(line, ball, velocity)));
            finite += time < Double.POSITIVE_INFINITY ? 1 : 0;
        }
        assertThat(finite).as("contacts found, and missed").isBetween(10_000, 290_000);
    }

    /** The method as it was written with vectors. */
    private static double withVectors(LineSegment line, Circle ball, Vect velocity) {
        Vect dir = line.p2().minus(line.p1());
        Vect normal = new Vect(-dir.y(), dir.x()).unitSize();
        Vect center = ball.getCenter();
        double offset = center.minus(line.p1()).dot(normal);
        double normalSpeed = velocity.dot(normal);
        double closingRate = offset == 0 ? Math.abs(normalSpeed) : Math.signum(offset) * normalSpeed;
        double gap = Math.abs(offset) - ball.getRadius();
        if (gap <= 0) {
            return closingRate < 0 && footOnFace(line, center) ? 0 : Double.POSITIVE_INFINITY;
        }
        if (closingRate >= 0) {
            return Double.POSITIVE_INFINITY;
        }
        double time = gap / -closingRate;
        if (time == Double.POSITIVE_INFINITY) {
            return time;
        }
        return footOnFace(line, center.plus(velocity.times(time))) ? time : Double.POSITIVE_INFINITY;
    }

    private static boolean footOnFace(LineSegment line, Vect point) {
        Vect dir = line.p2().minus(line.p1());
        return point.minus(line.p1()).dot(dir) >= 0 && line.p2().minus(point).dot(dir) > 0;
    }

    private static double coordinate(SplittableRandom random) {
        return random.nextInt(3) == 0 ? random.nextInt(41) / 2.0 : random.nextDouble(0, 20);
    }
}
