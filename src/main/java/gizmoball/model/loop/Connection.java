package gizmoball.model.loop;

import gizmoball.model.gizmo.Order;

/**
 * Whenever {@code source} (a gizmo or the outer walls) is hit, the gizmo {@code target} does what {@code order} says:
 * an action of its kind or, empty, its kind's default, at once or after a delay. A board holds at most one connection
 * from a source to a target.
 */
public record Connection(TriggerSource source, String target, Order order) {
    /** The connection of the standard format: the target's default action, at once. */
    public Connection(TriggerSource source, String target) {
        this(source, target, Order.DEFAULT);
    }

    /** Whether the two connect the same source to the same target, whatever they order. */
    public boolean sameEnds(Connection other) {
        return source.equals(other.source) && target.equals(other.target);
    }
}
