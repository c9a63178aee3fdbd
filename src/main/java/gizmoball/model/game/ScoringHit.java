package gizmoball.model.game;

/** A real hit that scored: in the tick numbered {@code tick} (ticks since the game's board was made), on that gizmo. */
public record ScoringHit(long tick, String gizmo, int points) {
}
