package gizmoball.model.game;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import java.awt.event.KeyEvent;

/**
 * The small game board of the game's rules tests: no gravity or friction; the bottom row is the drain and launcher,
 * Space fires the ball straight up into square S (125 points) 15.5 L away and it comes straight back into the drain,
 * {@link #TICKS_THERE_AND_BACK} ticks after the launch.
 */
final class LauncherBoards {
    static final double DT = Board.DEFAULT_TICK;
    static final int SPACE = KeyEvent.VK_SPACE;
    static final int TICKS_THERE_AND_BACK = (int) Math.ceil(2 * 15.5 / Board.ABSORBER_LAUNCH_SPEED / DT);

    private LauncherBoards() {
    }

    static Board launcherUnderASquare(int ballsPerGame) {
        Board board = new Board();
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addAbsorber("A", 0, 19, 20, 20);
        board.addGizmo(GizmoKind.SQUARE, "S", 19, 2);
        board.addBall("B", 19.75, 19.75, 0, 0);
        board.bindKey(SPACE, KeyEdge.DOWN, "A");
        board.setDrain("A", true);
        board.setBallsPerGame(ballsPerGame);
        board.setPoints("S", 125);
        return board;
    }

    /** Presses Space and plays until a ball drains; returns the ticks that took. */
    static int launchAndWait(Board board) {
        board.keyDown(SPACE);
        board.keyUp(SPACE);
        int drains = board.game().drains().size();
        for (int t = 1; t <= 2 * TICKS_THERE_AND_BACK; t++) {
            board.tick(DT);
            if (board.game().drains().size() > drains) {
                return t;
            }
        }
        throw new AssertionError("the ball did not drain within " + 2 * TICKS_THERE_AND_BACK + " ticks");
    }

    static void ticks(Board board, int n) {
        for (int i = 0; i < n; i++) {
            board.tick(DT);
        }
    }
}
