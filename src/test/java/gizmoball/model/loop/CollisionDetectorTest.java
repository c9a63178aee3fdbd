package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import physics.Circle;
import physics.Geometry;
import physics.LineSegment;
import physics.Vect;

/**
 * The detector's test of closing on a face, reckoned on the components (issue 39: no vector made per face asked),
 * answers what the Vect arithmetic it stands for answers, on random faces, balls, velocities and times, among them
 * faces along the axes, balls on the line and velocities that only graze. Its test of closing on a circle, which
 * takes lengths by square roots first, answers what it answers with physics-lib's lengths, near its thresholds too;
 * and what lies outside a ball's swept box is never met in the window.
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

            assertThat(CollisionDetector.closesOnSegment(face, ball, velocity.x(), velocity.y(), time)).as("case %d", i)
                    .isEqualTo(expected);
            closing += expected ? 1 : 0;
        }
        assertThat(closing).as("both answers are asked for").isBetween(20_000, 180_000);
    }

    @Test
    void closingOnACircleIsTheAnswerWithPhysicsLibsLengths() {
        SplittableRandom random = new SplittableRandom(3939);
        int closing = 0;
        for (int i = 0; i < 300_000; i++) {
            double touch = random.nextBoolean() ? 2 * Arena.BALL_RADIUS : Arena.BALL_RADIUS + random.nextDouble(0, 1);
            double angle = random.nextDouble(0, 2 * Math.PI);
            Vect away = random.nextInt(8) == 0 ? new Vect(random.nextBoolean() ? touch : -touch, 0)
                    : new Vect(touch * Math.cos(angle), touch * Math.sin(angle));
            Vect normal = away.times(1 / away.length());
            Vect tangent = new Vect(-normal.y(), normal.x());
            double speed = switch (random.nextInt(4)) {
                case 0 -> random.nextDouble(0, 1e-8);   // about the rounding speed
                case 1 -> random.nextDouble(0, 1e-300);   // squares that underflow
                default -> random.nextDouble(0, 100);
            };
            double closingPart = switch (random.nextInt(5)) {
                case 0 -> Tolerances.GRAZE_ANGLE * (1 + random.nextDouble(-1e-9, 1e-9));   // at the graze angle
                case 1 -> Math.sqrt(2 * Tolerances.PLACEMENT / touch) * (1 + random.nextDouble(-1e-6, 1e-6));
                case 2 -> 0;
                default -> random.nextDouble(-1, 1);
            };
            Vect relative = normal.times(-closingPart * speed).plus(tangent.times(speed));

            boolean expected = closingWithHypot(away, relative);

            assertThat(CollisionDetector.closingOnCircle(away, relative)).as("case %d", i).isEqualTo(expected);
            closing += expected ? 1 : 0;
        }
        assertThat(closing).as("both answers are asked for").isBetween(30_000, 270_000);
    }

    /** What closing on a circle means, with the lengths as physics-lib's Vect gives them. */
    private static boolean closingWithHypot(Vect away, Vect relative) {
        double length = away.length();
        double closing = length > 0 ? -relative.dot(away) / length : 0;
        return closing > Math.max(Tolerances.ROUNDING_SPEED, Tolerances.GRAZE_ANGLE * relative.length())
                && !Kinematics.grazes(away, relative, length);
    }

    @Test
    void whatLiesOutsideTheSweptBoxIsNotMetInTheWindow() {
        SplittableRandom random = new SplittableRandom(393939);
        SweptBox box = new SweptBox();
        int missed = 0;
        for (int i = 0; i < 200_000; i++) {
            Vect centre = new Vect(coordinate(random), coordinate(random));
            Vect velocity = new Vect(random.nextDouble(-100, 100),
                    random.nextInt(8) == 0 ? 0 : random.nextDouble(-100, 100));
            double window = random.nextDouble(0, 1.0 / 60);
            box.set(centre.x(), centre.y(), velocity.x(), velocity.y(), window);
            Circle ball = new Circle(centre, Arena.BALL_RADIUS);
            LineSegment face = new LineSegment(coordinate(random), coordinate(random), coordinate(random),
                    coordinate(random));
            Circle circle = new Circle(coordinate(random), coordinate(random),
                    random.nextInt(2) * random.nextDouble(0, 1));
            if (box.misses(face)) {
                missed++;
                assertThat(Geometry.timeUntilWallCollision(face, ball, velocity)).as("case %d", i)
                        .isGreaterThan(window);
            }
            if (box.misses(circle)) {
                missed++;
                assertThat(Geometry.timeUntilCircleCollision(circle, ball, velocity)).as("case %d", i)
                        .isGreaterThan(window);
            }
        }
        assertThat(missed).as("shapes outside the box are asked about").isGreaterThan(100_000);
    }

    /** A coordinate on the board, often a whole or half number as gizmos have them. */
    private static double coordinate(SplittableRandom random) {
        return random.nextInt(3) == 0 ? random.nextInt(41) / 2.0 : random.nextDouble(0, 20);
    }
}
