package gizmoball.controller.editor;

import gizmoball.model.Ball;
import gizmoball.model.Board;
import gizmoball.model.Connection;
import gizmoball.model.Gizmo;
import gizmoball.model.GizmoKind;
import gizmoball.model.KeyBinding;

import java.util.List;

/** Everything a board file says about a board, as comparable values (the model has no equals on Board). */
record BoardContents(List<GizmoState> gizmos, List<BallState> balls, List<Connection> connections,
                     List<KeyBinding> keys, double gravity, double mu, double mu2) {
    record GizmoState(String name, GizmoKind kind, int x, int y, int width, int height, int rotation) { }

    record BallState(String name, double x, double y, double vx, double vy) { }

    static BoardContents of(Board board) {
        return new BoardContents(
                board.gizmos().stream().map(BoardContents::state).toList(),
                board.balls().stream().map(BoardContents::state).toList(),
                List.copyOf(board.connections()), List.copyOf(board.keyBindings()),
                board.gravity(), board.mu(), board.mu2());
    }

    private static GizmoState state(Gizmo g) {
        return new GizmoState(g.name(), g.kind(), g.x(), g.y(), g.width(), g.height(), g.rotation());
    }

    private static BallState state(Ball b) {
        return new BallState(b.name(), b.position().x(), b.position().y(), b.velocity().x(), b.velocity().y());
    }
}
