package gizmoball.stability;

import gizmoball.model.Board;
import gizmoball.model.LoopModes;
import gizmoball.model.loop.LoopMode;

/** Boards without gravity or friction, where the outcomes of the stability scenes are exact. */
final class FreeSpace {

    private FreeSpace() {
    }

    /** An empty board with no gravity and no friction, ticked by the given loop. */
    static Board board(LoopMode mode) {
        Board board = new Board();
        LoopModes.set(board, mode);
        board.setGravity(0);
        board.setFriction(0, 0);
        return board;
    }
}
