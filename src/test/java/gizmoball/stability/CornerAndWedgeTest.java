package gizmoball.stability;

import gizmoball.model.Board;
import gizmoball.model.LoopModes;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.LoopMode;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import physics.Vect;

import static org.assertj.core.api.Assertions.assertThat;

/**
 * Failure mode (docs/design.md, "Failure modes": corners and wedges): a ball in a corner or a wedge, where two surfaces are hit within one tick
 * (or at once) over and over. Resolving one collision per tick loses time; resolving several must not
 * loop for ever, push the ball through either surface, or pump energy in.
 */
class CornerAndWedgeTest {

    private static final double DT = Board.DEFAULT_TICK;
    private static final double R = Board.BALL_RADIUS;

    /**
     * A V of triangles: 45-degree arms (y = x + 4 on the left, y = 24 - x on the right) meeting at
     * (10, 14) in a 90-degree wedge. A ball dropped onto the left arm bounces and rolls in the V.
     */
    static Board vOfTriangles() {
        Board board = new Board();
        String[] names = {"L1", "L2", "L3", "R1", "R2", "R3"};
        int[][] cells = {{7, 11}, {8, 12}, {9, 13}, {10, 13}, {11, 12}, {12, 11}};
        int[] turns = {3, 3, 3, 2, 2, 2};   // 3: bottom-left half-cell, 2: bottom-right half-cell
        for (int i = 0; i < names.length; i++) {
            board.addGizmo(GizmoKind.TRIANGLE, names[i], cells[i][0], cells[i][1]);
            for (int t = 0; t < turns[i]; t++) {
                board.rotate(names[i]);
            }
        }
        return board;
    }

    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void ballInAVOfTrianglesNeverEntersAnArm(LoopMode mode) {
        Board board = vOfTriangles();
        LoopModes.set(board, mode);
        board.addBall("B", 8, 9, 0, 0);
        double impactSpeed = Math.sqrt(2 * board.gravity() * (Board.SIZE - R - 9));   // fastest: down to the floor
        Vect top1 = new Vect(7, 11);
        Vect bottom = new Vect(10, 14);
        Vect top2 = new Vect(13, 11);
        new Watch("V of triangles", board, DT).allowEnergyGainOfOneTickAt(impactSpeed).run(3000, (tick, b) -> {
            Vect p = b.balls().get(0).position();
            // The arms' slanted faces, seams included: a ball closer than its radius is inside a triangle.
            assertThat(Math.min(Shapes.toSegment(top1, bottom, p), Shapes.toSegment(bottom, top2, p)))
                    .as("clearance from the arms at tick " + tick + ", ball at " + p).isGreaterThanOrEqualTo(R - 1e-6);
        });
    }

    /** Thrown diagonally into a corner of the board, again and again under gravity. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void ballThrownIntoTheBoardCorners(LoopMode mode) {
        Board board = new Board();
        LoopModes.set(board, mode);
        board.addBall("B", 17, 17, 30, 30);
        double speed = Math.sqrt(2 * 30 * 30 + 2 * board.gravity() * 20);
        new Watch("thrown into a corner", board, DT).allowEnergyGainOfOneTickAt(speed).run(3000);
    }

    /** Rolling along the floor into the 90-degree corner between the floor and a square standing on it. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void ballRollingIntoTheCornerOfTheFloorAndASquare(LoopMode mode) {
        Board board = new Board();
        LoopModes.set(board, mode);
        board.addGizmo(GizmoKind.SQUARE, "S", 10, 19);
        board.addBall("B", 6, Board.SIZE - R, 4, 0);
        new Watch("square on the floor", board, DT).allowEnergyGainOfOneTickAt(4 + board.gravity() * DT).run(3000,
                (tick, b) -> assertThat(b.balls().get(0).position().x()).as("left of the square at tick " + tick)
                        .isLessThanOrEqualTo(10 - R + 1e-6));
    }
}
