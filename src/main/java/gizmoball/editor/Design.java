package gizmoball.editor;

import gizmoball.model.Ball;
import gizmoball.model.Board;
import gizmoball.model.Connection;
import gizmoball.model.Gizmo;
import gizmoball.model.GizmoKind;
import gizmoball.model.KeyBinding;

import java.util.List;

/**
 * Everything a board file says about a board, as comparable values (Board itself has no equality): the editor
 * uses it to tell whether a change made elsewhere (Open, back from play, another menu) altered the design.
 */
public record Design(List<GizmoState> gizmos, List<BallState> balls, List<Connection> connections,
                     List<KeyBinding> keys, double gravity, double mu, double mu2) {
    public record GizmoState(String name, GizmoKind kind, int x, int y, int width, int height, int rotation) { }

    public record BallState(String name, double x, double y, double vx, double vy) { }

    public static Design of(Board board) {
        return new Design(
                board.gizmos().stream().map(Design::state).toList(),
                board.balls().stream().map(Design::state).toList(),
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
