package gizmoball.model.loop;

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

    private Arena() {
    }
}
