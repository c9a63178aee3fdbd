package gizmoball.model;

import gizmoball.model.gizmo.Order;

/**
 * Pressing ({@link KeyEdge#DOWN}) or releasing ({@link KeyEdge#UP}) the key {@code keyCode} drives {@code gizmo} as
 * {@code order} says: an action of its own or, empty, what that edge makes it do ({@link KeyEdge#actionOf}), at once
 * or after a delay. A board holds at most one binding of a key's edge to a gizmo.
 */
public record KeyBinding(int keyCode, KeyEdge edge, String gizmo, Order order) {
    /** The binding of the standard format: what the edge makes the gizmo do, at once. */
    public KeyBinding(int keyCode, KeyEdge edge, String gizmo) {
        this(keyCode, edge, gizmo, Order.DEFAULT);
    }

    /** Whether the two bind the same edge of the same key to the same gizmo, whatever they order. */
    boolean sameEdgeOfKey(KeyBinding other) {
        return keyCode == other.keyCode && edge == other.edge && gizmo.equals(other.gizmo);
    }
}
