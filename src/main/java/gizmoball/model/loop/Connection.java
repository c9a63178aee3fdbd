package gizmoball.model.loop;

/** Whenever {@code source} (a gizmo or the outer walls) is hit, the gizmo {@code target} performs its action. */
public record Connection(TriggerSource source, String target) {
}
