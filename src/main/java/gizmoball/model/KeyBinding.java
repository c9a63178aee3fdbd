package gizmoball.model;

/** Pressing ({@link KeyEdge#DOWN}) or releasing ({@link KeyEdge#UP}) the key {@code keyCode} drives {@code gizmo}. */
public record KeyBinding(int keyCode, KeyEdge edge, String gizmo) {
}
