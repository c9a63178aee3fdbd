package gizmoball.model;

import gizmoball.model.gizmo.FlipperView;

import java.util.stream.Collectors;

/** A complete textual description of a board's state, for comparing boards in tests. */
final class BoardSnapshot {
    private BoardSnapshot() {
    }

    static String of(Board board) {
        String gizmos = board.gizmos().stream().map(g -> {
            String base = g.kind() + " " + g.name() + " " + g.x() + "," + g.y() + " " + g.width() + "x" + g.height()
                    + " r" + g.rotation() + " t" + g.lastTriggeredAt();
            if (g instanceof FlipperView f) {
                base += " angle " + f.angleFromRest() + " active " + f.isActive();
            }
            return base;
        }).collect(Collectors.joining("\n"));
        String balls = board.balls().stream()
                .map(b -> b.name() + " " + b.position() + " " + b.velocity() + " " + b.isCaptured())
                .collect(Collectors.joining("\n"));
        return gizmos + "\n--\n" + balls + "\n--\n" + board.connections() + "\n" + board.keyBindings()
                + "\ng " + board.gravity() + " mu " + board.mu() + " mu2 " + board.mu2() + " time " + board.time()
                + " " + board.loopView().loopMode();
    }
}
