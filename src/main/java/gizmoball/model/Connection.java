package gizmoball.model;

/** Whenever {@code source} is hit (a gizmo or {@link Board#OUTER_WALLS}), {@code target} performs its action. */
public record Connection(String source, String target) {
}
