package gizmoball.model.gizmo;

/**
 * What play has changed of a gizmo beyond what its author built (a flipper's swing, a cell opened, a spinner's turn):
 * what a save during play writes, so that the board loads again as it was. Each kind answers its own
 * ({@link Gizmo#playState}), so that the writer asks the gizmo, not which kind it is.
 */
public sealed interface PlayState {
    /** As built: nothing to write. Every kind that play does not change, and any gizmo play has left at rest. */
    record AsBuilt() implements PlayState {
    }

    /** A flipper moved from rest: its angle from rest in degrees, and whether it is up or swinging up. */
    record Swung(double degrees, boolean up) implements PlayState {
    }

    /** A cell that play has made nothing: a gate opened, a drop target knocked down. */
    record Opened() implements PlayState {
    }

    /** A spinner turned from its start or stopped: its angle in radians, and whether it turns. */
    record Turned(double radians, boolean running) implements PlayState {
    }
}
