package gizmoball.editor;

import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.loop.BallView;
import java.util.Comparator;
import java.util.Optional;

/**
 * What a pointer in board coordinates (L) is over: the cell, a ball near it, the gizmo there, the outer walls;
 * and where a ball dropped there snaps to. The tools read the board through it to find what a click means.
 */
final class Picking {
    /** Ball centres snap to quarter cells: positions stay readable in saved files and easy to hit again. */
    static final double BALL_SNAP = 0.25;
    /** Pixels are coarse: a ball (radius 0.25 L) is picked within this distance of its centre. */
    static final double BALL_PICK_DISTANCE = 0.4;
    /** Clicks this close to the board's edge, on an empty cell, mean the outer walls (Connect tools). */
    static final double WALL_BAND = 0.25;
    /** A press that moves less than this is a click, not a drag. */
    static final double DRAG_THRESHOLD = 0.1;

    private final Board board;

    Picking(Board board) {
        this.board = board;
    }

    Optional<Gizmo> gizmoAt(double x, double y) {
        return board.gizmoAt(cell(x), cell(y));
    }

    Optional<BallView> ballNear(double x, double y) {
        return board.balls().stream()
                .filter(b -> Math.hypot(b.position().x() - x, b.position().y() - y) <= BALL_PICK_DISTANCE)
                .min(Comparator.comparingDouble(b -> Math.hypot(b.position().x() - x, b.position().y() - y)));
    }

    /** The name of the ball or else the gizmo under the point: a ball first, as it may sit on a gizmo's cell. */
    Optional<String> ballOrGizmoAt(double x, double y) {
        return ballNear(x, y).map(BallView::name).or(() -> gizmoAt(x, y).map(Gizmo::name));
    }

    boolean isWall(double x, double y) {
        boolean outside = x < 0 || y < 0 || x >= Board.SIZE || y >= Board.SIZE;
        boolean nearEdge = x < WALL_BAND || y < WALL_BAND || x > Board.SIZE - WALL_BAND || y > Board.SIZE - WALL_BAND;
        return outside || (nearEdge && gizmoAt(x, y).isEmpty());
    }

    static int cell(double v) {
        return (int) Math.floor(v);
    }

    static double snap(double v) {
        return Math.round(v / BALL_SNAP) * BALL_SNAP;
    }
}
