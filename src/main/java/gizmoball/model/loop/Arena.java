package gizmoball.model.loop;

import java.util.List;

import physics.LineSegment;

/**
 * The square the balls play in and the balls' own measures: constants of the loop, which may not see the board.
 * The board names them for its users too ({@code Board.SIZE}, {@code Board.BALL_RADIUS}, {@code Board.MAX_SPEED}
 * are these).
 */
public final class Arena {
    /** L (and cells): the side of the square, walled by the outer walls. */
    public static final int SIZE = 20;
    /** L: the radius of every ball. */
    public static final double BALL_RADIUS = 0.25;
    /** L/s: no ball moves faster. */
    public static final double MAX_SPEED = 200;
    /** The outer walls, by side: 0 the top (y = 0), then clockwise on the screen: right, bottom, left. */
    static final List<LineSegment> OUTER_WALLS = List.of(
            new LineSegment(0, 0, SIZE, 0),
            new LineSegment(SIZE, 0, SIZE, SIZE),
            new LineSegment(SIZE, SIZE, 0, SIZE),
            new LineSegment(0, SIZE, 0, 0));

    private Arena() {
    }

    /**
     * The column or row of the cell that holds the coordinate (L), the outermost one for a coordinate beyond the
     * square, the first for a NaN: floor clamped to [0, SIZE - 1], by comparisons (each coordinate of a box a ball
     * sweeps asks, several times a ball and collision).
     */
    static int cellOf(double coordinate) {
        if (coordinate < 1) {
            return 0;
        }
        return coordinate >= SIZE - 1 ? SIZE - 1 : (int) coordinate;   // truncation is floor from 1 on; NaN gives 0
    }
}
