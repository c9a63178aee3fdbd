package gizmoball.model;

/** Something audible or visible that happened in play, reported with the tick it happened in (for sound, flashes). */
public sealed interface PlayEvent {

    /**
     * A ball hit a gizmo, the outer walls ({@code kind} null, {@code source} {@link Board#OUTER_WALLS}) or another
     * ball ({@code kind} null, {@code source} null), closing at {@code speed} L/s along the contact normal.
     */
    record Hit(String source, GizmoKind kind, double speed) implements PlayEvent {
    }

    /** An absorber captured a ball. */
    record Captured(String absorber) implements PlayEvent {
    }

    /** An absorber fired a ball. */
    record Fired(String absorber) implements PlayEvent {
    }

    /** A flipper started swinging, {@code up} toward its active position or back down. */
    record Swing(String flipper, boolean up) implements PlayEvent {
    }
}
