package gizmoball.bench;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import physics.Vect;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

/** The five scenes of the benchmark. */
final class Scenes {

    static final int LEFT_FLIPPER_KEY = 90;   // Z
    static final int RIGHT_FLIPPER_KEY = 47;  // slash

    private Scenes() {
    }

    static List<Scene> all(Path scripts) throws IOException {
        return List.of(elasticBox(), bouncingBall(), denseBoard(),
                flipperRally(KeyScript.read(scripts.resolve("flipper-rally.keys"))), cornersAndResting());
    }

    /**
     * One ball, no gravity, no friction, walls only. Reflections off the walls of a box unfold into a
     * straight line: each coordinate moves uniformly and is folded back into [r, SIZE - r].
     */
    static Scene elasticBox() {
        double x0 = 3.3, y0 = 7.1, vx = 13.7, vy = -9.1;
        double lo = Board.BALL_RADIUS, hi = Board.SIZE - Board.BALL_RADIUS;
        return new Scene("elastic box", 10, () -> {
            Board b = new Board();
            b.setGravity(0);
            b.setFriction(0, 0);
            b.addBall("B", x0, y0, vx, vy);
            return b;
        }, KeyScript.NONE, Optional.of(t -> List.of(new Vect(fold(x0 + vx * t, lo, hi), fold(y0 + vy * t, lo, hi)))),
                Optional.empty());
    }

    /** Position of a point moving uniformly along a line, folded into [lo, hi] by mirror reflections. */
    static double fold(double u, double lo, double hi) {
        double width = hi - lo;
        double m = (u - lo) % (2 * width);
        if (m < 0) {
            m += 2 * width;
        }
        return lo + (m <= width ? m : 2 * width - m);
    }

    /**
     * A ball dropped from rest onto the elastic floor, gravity only. It falls for t_f = sqrt(2h/g) and
     * rises for as long, back to its start height, for ever: y(t) = y0 + g/2 (t_f - |tau - t_f|)^2 with
     * tau = t mod 2 t_f.
     */
    static Scene bouncingBall() {
        double x0 = 10.5, y0 = 5, g = Board.DEFAULT_GRAVITY;
        double floor = Board.SIZE - Board.BALL_RADIUS;
        double fall = Math.sqrt(2 * (floor - y0) / g);
        return new Scene("bouncing ball", 10, () -> {
            Board b = new Board();
            b.setGravity(g);
            b.setFriction(0, 0);
            b.addBall("B", x0, y0, 0, 0);
            return b;
        }, KeyScript.NONE, Optional.of(t -> {
            double tau = t % (2 * fall);
            double s = fall - Math.abs(tau - fall);
            return List.of(new Vect(x0, y0 + g / 2 * s * s));
        }), Optional.of(y0));
    }

    /**
     * 60 bumpers and 6 balls under default gravity and friction; no closed form. Bounces off round
     * bumpers magnify any difference, so the horizon is short: by 0.5 s the balls have hit their first
     * bumpers, and beyond about 1 s every method has drifted a few L from the reference (chaos).
     */
    static Scene denseBoard() {
        return new Scene("dense board", 0.5, Scenes::denseBoardOnly, KeyScript.NONE, Optional.empty(), Optional.empty());
    }

    static Board denseBoardOnly() {
        return RandomBoards.generate(7, 60, 6);
    }

    /**
     * Two flippers on a timed key script: a ball dropped above the left flipper is batted by it while it
     * swings up, and flies on across the board for half a second (longer horizons only add chaos).
     */
    static Scene flipperRally(KeyScript keys) {
        return new Scene("flipper rally", 1.5, () -> {
            Board b = new Board();
            b.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 8, 15);
            b.addGizmo(GizmoKind.RIGHT_FLIPPER, "RF", 11, 15);
            b.bindKey(LEFT_FLIPPER_KEY, KeyEdge.DOWN, "LF");
            b.bindKey(LEFT_FLIPPER_KEY, KeyEdge.UP, "LF");
            b.bindKey(RIGHT_FLIPPER_KEY, KeyEdge.DOWN, "RF");
            b.bindKey(RIGHT_FLIPPER_KEY, KeyEdge.UP, "RF");
            b.addGizmo(GizmoKind.SQUARE, "S1", 4, 6);
            b.addGizmo(GizmoKind.CIRCLE, "C1", 15, 8);
            b.addBall("B", 9.1, 4, 0, 0);
            return b;
        }, keys, Optional.empty(), Optional.empty());
    }

    /**
     * A V of triangles (45-degree slopes meeting in a 90-degree wedge, with seams between the triangles
     * along each arm), a ball dropped onto one arm to roll and settle in the wedge, a ball resting on a
     * square bumper and one resting on the floor.
     */
    static Scene cornersAndResting() {
        return new Scene("corners and resting", 5, () -> {
            Board b = new Board();
            // Left arm: bottom-left half-cells (rotation 3), slope from (7,11) down to (10,14).
            addTriangle(b, "L1", 7, 11, 3);
            addTriangle(b, "L2", 8, 12, 3);
            addTriangle(b, "L3", 9, 13, 3);
            // Right arm: bottom-right half-cells (rotation 2), slope from (10,14) up to (13,11).
            addTriangle(b, "R1", 10, 13, 2);
            addTriangle(b, "R2", 11, 12, 2);
            addTriangle(b, "R3", 12, 11, 2);
            b.addGizmo(GizmoKind.SQUARE, "S", 3, 15);
            b.addBall("V", 8.0, 9.0, 0, 0);
            b.addBall("OnSquare", 3.5, 15 - Board.BALL_RADIUS, 0, 0);
            b.addBall("OnFloor", 17.5, Board.SIZE - Board.BALL_RADIUS, 0, 0);
            return b;
        }, KeyScript.NONE, Optional.empty(), Optional.empty());
    }

    private static void addTriangle(Board b, String name, int x, int y, int quarterTurns) {
        b.addGizmo(GizmoKind.TRIANGLE, name, x, y);
        for (int i = 0; i < quarterTurns; i++) {
            b.rotate(name);
        }
    }
}
