package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import physics.Circle;
import physics.Geometry;
import physics.LineSegment;
import physics.Vect;

/**
 * Where {@link Approach} says a ball cannot meet a line or a circle in the time left, the detector's own answer (the
 * API's time within that time, and closing as the detector requires) is no: on random faces and circles, balls
 * clear of them at any distance and velocities any way, among them faces along the axes, velocities along the face
 * and balls just touching. Both answers are asked for, so the tests pass over something and keep something.
 */
class ApproachTest {
    @Test
    void aLineItSaysCannotBeMetIsNotMet() {
        SplittableRandom random = new SplittableRandom(3901);
        int refused = 0;
        for (int i = 0; i < 200_000; i++) {
            double x1 = coordinate(random);
            double y1 = coordinate(random);
            boolean axis = random.nextInt(3) == 0;
            double x2 = axis && random.nextBoolean() ? x1 : coordinate(random);
            double y2 = axis && x2 != x1 ? y1 : coordinate(random);
            LineSegment face = new LineSegment(x1, y1, x2, y2);
            Vect centre = clearOf(face, random);
            Vect velocity = velocity(random, new Vect(x2 - x1, y2 - y1));
            double within = random.nextDouble(0, 0.05);
            Ball ball = new Ball("B", centre, velocity);

            boolean may = Approach.mayMeetLine(face, centre.x(), centre.y(), velocity.x(), velocity.y(), within);

            double time = Geometry.timeUntilWallCollision(face, ball.circle(), velocity);
            boolean met = time <= within && CollisionDetector.closesOnSegment(face, ball, velocity.x(), velocity.y(), time);
            if (!may) {
                assertThat(met).as("case %d: %s, ball at %s moving %s, %s s", i, face, centre, velocity, within)
                        .isFalse();
                refused++;
            }
        }
        assertThat(refused).as("both answers are given").isBetween(20_000, 190_000);
    }

    @Test
    void aCircleItSaysCannotBeMetIsNotMet() {
        SplittableRandom random = new SplittableRandom(3902);
        int refused = 0;
        for (int i = 0; i < 200_000; i++) {
            Circle circle = new Circle(coordinate(random), coordinate(random),
                    random.nextInt(4) == 0 ? 0 : random.nextDouble(0, 1.5));
            double touch = circle.getRadius() + Arena.BALL_RADIUS;
            double angle = random.nextDouble(0, 2 * Math.PI);
            double distance = touch + (random.nextInt(5) == 0 ? random.nextDouble(0, 1e-9) : random.nextDouble(0, 5));
            Vect centre = circle.getCenter().plus(new Vect(distance * Math.cos(angle), distance * Math.sin(angle)));
            Vect velocity = velocity(random, circle.getCenter().minus(centre));
            double within = random.nextDouble(0, 0.05);
            Ball ball = new Ball("B", centre, velocity);

            boolean may = Approach.mayMeetCircle(circle, centre.x(), centre.y(), velocity.x(), velocity.y(), within);

            double time = Geometry.timeUntilCircleCollision(circle, ball.circle(), velocity);
            boolean met = time <= within && CollisionDetector.closingOnCircle(
                    centre.plus(velocity.times(time)).minus(circle.getCenter()), velocity);
            if (!may) {
                assertThat(met).as("case %d: %s, ball at %s moving %s, %s s", i, circle, centre, velocity, within)
                        .isFalse();
                refused++;
            }
        }
        assertThat(refused).as("both answers are given").isBetween(20_000, 190_000);
    }

    private static double coordinate(SplittableRandom random) {
        return random.nextInt(4) == 0 ? random.nextInt(21) : random.nextDouble(0, 20);
    }

    /** A centre at least a ball's radius from the face: beside it at any distance, or past one of its ends. */
    private static Vect clearOf(LineSegment face, SplittableRandom random) {
        Vect p1 = face.p1();
        Vect along = face.p2().minus(p1);
        double length = along.length();
        Vect unit = length == 0 ? new Vect(1, 0) : along.times(1 / length);
        Vect normal = new Vect(-unit.y(), unit.x());
        double side = random.nextBoolean() ? 1 : -1;
        double gap = random.nextInt(5) == 0 ? random.nextDouble(0, 1e-9) : random.nextDouble(0, 5);
        double at = random.nextDouble(-1, length + 1);
        return p1.plus(unit.times(at)).plus(normal.times(side * (Arena.BALL_RADIUS + gap)));
    }

    /** Any way, along {@code special} (a face, or toward a centre) one time in five, some along an axis. */
    private static Vect velocity(SplittableRandom random, Vect special) {
        double speed = random.nextDouble(0, 200);
        if (random.nextInt(5) == 0 && special.length() > 0) {
            return special.times((random.nextBoolean() ? speed : -speed) / special.length());
        }
        double angle = random.nextInt(6) == 0 ? random.nextInt(4) * Math.PI / 2 : random.nextDouble(0, 2 * Math.PI);
        return new Vect(speed * Math.cos(angle), speed * Math.sin(angle));
    }
}
