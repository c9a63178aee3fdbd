package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.gizmo.GizmoKind;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import physics.Vect;

/**
 * A ball aimed at each face and corner of each bumper, in every rotation, leaves with the mirror image of its
 * velocity about the contact normal: v' = v - 2 (v.n) n. Cases are set up for the unrotated bumper in cell
 * (10, 10) and turned with it about the cell centre.
 */
class BumperReflectionTest {
    private static final double R = Board.BALL_RADIUS;
    private static final Vect CENTRE = new Vect(10.5, 10.5);

    record Shot(String what, GizmoKind kind, Vect start, Vect velocity, Vect expected) {
        @Override
        public String toString() {
            return kind + " " + what;
        }
    }

    static Vect reflect(Vect v, Vect normal) {
        Vect n = normal.unitSize();
        return v.minus(n.times(2 * v.dot(n)));
    }

    /** A ball moving from start with velocity v against a circle (centre c, radius rc): normal at first contact. */
    static Vect offCircle(Vect start, Vect v, Vect c, double rc) {
        // |start + v t - c| = rc + R: the smaller root of |v|^2 t^2 + 2 v.(start - c) t + |start - c|^2 - (rc + R)^2
        Vect d = start.minus(c);
        double a = v.dot(v);
        double b = 2 * v.dot(d);
        double cc = d.dot(d) - (rc + R) * (rc + R);
        double t = (-b - Math.sqrt(b * b - 4 * a * cc)) / (2 * a);
        return reflect(v, start.plus(v.times(t)).minus(c));
    }

    static List<Shot> unrotated() {
        List<Shot> shots = new ArrayList<>();
        Vect down = new Vect(0, 10);
        for (GizmoKind kind : List.of(GizmoKind.SQUARE, GizmoKind.TRIANGLE)) {
            shots.add(new Shot("top face", kind, new Vect(10.3, 8.5), new Vect(2, 10), new Vect(2, -10)));
            shots.add(new Shot("left face", kind, new Vect(8.5, 10.3), new Vect(10, -1), new Vect(-10, -1)));
            shots.add(new Shot("top-left corner on the diagonal", kind, new Vect(9, 9), new Vect(7, 7), new Vect(-7, -7)));
            Vect start = new Vect(9.9, 8.5);
            shots.add(new Shot("top-left corner from above", kind, start, down, offCircle(start, down, new Vect(10, 10), 0)));
            start = new Vect(11.1, 8.5);
            shots.add(new Shot("top-right corner from above", kind, start, down, offCircle(start, down, new Vect(11, 10), 0)));
        }
        shots.add(new Shot("bottom face", GizmoKind.SQUARE, new Vect(10.6, 12.5), new Vect(-1, -10), new Vect(-1, 10)));
        shots.add(new Shot("right face", GizmoKind.SQUARE, new Vect(12.5, 10.6), new Vect(-10, 3), new Vect(10, 3)));
        Vect up = new Vect(0, -10);
        Vect start = new Vect(11.2, 12.5);
        shots.add(new Shot("bottom-right corner from below", GizmoKind.SQUARE, start, up,
                offCircle(start, up, new Vect(11, 11), 0)));
        // the hypotenuse x + y = 21 faces down-right, normal (1, 1)
        shots.add(new Shot("hypotenuse", GizmoKind.TRIANGLE, new Vect(12.5, 10.5), new Vect(-10, 0), new Vect(0, 10)));
        shots.add(new Shot("hypotenuse obliquely", GizmoKind.TRIANGLE, new Vect(11.5, 12.0), new Vect(-4, -9),
                reflect(new Vect(-4, -9), new Vect(1, 1))));
        start = new Vect(9.8, 12.5);
        shots.add(new Shot("bottom-left corner from below", GizmoKind.TRIANGLE, start, up,
                offCircle(start, up, new Vect(10, 11), 0)));
        shots.add(new Shot("centre", GizmoKind.CIRCLE, new Vect(10.5, 8), down, new Vect(0, -10)));
        start = new Vect(10.2, 8);
        shots.add(new Shot("off centre", GizmoKind.CIRCLE, start, down, offCircle(start, down, CENTRE, 0.5)));
        start = new Vect(8, 10.9);
        shots.add(new Shot("glancing", GizmoKind.CIRCLE, start, new Vect(10, 0),
                offCircle(start, new Vect(10, 0), CENTRE, 0.5)));
        return shots;
    }

    /** Clockwise quarter turns about the cell centre (y down: (dx, dy) -> (-dy, dx)). */
    static Vect turn(Vect v, int quarterTurns, boolean aboutCentre) {
        Vect d = aboutCentre ? v.minus(CENTRE) : v;
        for (int i = 0; i < quarterTurns; i++) {
            d = new Vect(-d.y(), d.x());
        }
        return aboutCentre ? CENTRE.plus(d) : d;
    }

    static Stream<Arguments> shots() {
        return unrotated().stream().flatMap(shot -> Stream.of(0, 1, 2, 3)
                .map(rotation -> Arguments.of(shot, rotation)));
    }

    @ParameterizedTest(name = "{0}, rotation {1}")
    @MethodSource("shots")
    void leavesWithTheVelocityMirroredAboutTheContactNormal(Shot shot, int rotation) {
        Board board = new Board();
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addGizmo(shot.kind(), "G", 10, 10);
        for (int i = 0; i < rotation; i++) {
            board.rotate("G");
        }
        Vect start = turn(shot.start(), rotation, true);
        board.addBall("B", start.x(), start.y(), turn(shot.velocity(), rotation, false).x(),
                turn(shot.velocity(), rotation, false).y());
        for (int i = 0; i < 15; i++) {   // 0.25 s: one hit, and not yet the outer walls
            board.tick(Board.DEFAULT_TICK);
        }
        Vect expected = turn(shot.expected(), rotation, false);
        Vect actual = board.ball("B").orElseThrow().velocity();
        assertThat(actual.x()).as("vx").isCloseTo(expected.x(), within(1e-9));
        assertThat(actual.y()).as("vy").isCloseTo(expected.y(), within(1e-9));
        assertThat(board.gizmo("G").orElseThrow().lastTriggeredAt()).as("the hit is recorded").isFinite();
    }
}
