package gizmoball.model.game;

/** A ball lost: the drain {@code absorber} captured it in the tick numbered {@code tick}. */
public record Drain(long tick, String ball, String absorber) {
}
