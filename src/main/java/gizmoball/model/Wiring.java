package gizmoball.model;

import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/** What drives which gizmo: the connections from trigger sources and the key bindings, in the order made. */
final class Wiring {
    private final Registry registry;
    private final List<Connection> connections = new ArrayList<>();
    private final List<KeyBinding> keyBindings = new ArrayList<>();
    /**
     * The connections as an unchangeable list and grouped by source, made again after each change (null until
     * asked): the loop asks for those of a source at every collision, and a copy each time cost a dense board a
     * tenth of its tick.
     */
    private List<Connection> snapshot;
    private Map<TriggerSource, List<Connection>> bySource;

    Wiring(Registry registry) {
        this.registry = registry;
    }

    void copyFrom(Wiring source) {
        clear();
        connections.addAll(source.connections);
        keyBindings.addAll(source.keyBindings);
        changed();
    }

    void clear() {
        connections.clear();
        keyBindings.clear();
        changed();
    }

    private void changed() {
        snapshot = null;
        bySource = null;
    }

    List<Connection> connections() {
        if (snapshot == null) {
            snapshot = List.copyOf(connections);
        }
        return snapshot;
    }

    /** The connections from {@code source}, in the order made. */
    List<Connection> connectionsFrom(TriggerSource source) {
        if (bySource == null) {
            Map<TriggerSource, List<Connection>> grouped = new HashMap<>();
            for (Connection c : connections) {
                grouped.computeIfAbsent(c.source(), s -> new ArrayList<>()).add(c);
            }
            grouped.replaceAll((s, list) -> List.copyOf(list));
            bySource = grouped;
        }
        return bySource.getOrDefault(source, List.of());
    }

    List<KeyBinding> keyBindings() {
        return List.copyOf(keyBindings);
    }

    void connect(TriggerSource source, String target, Order order) {
        if (source == null) {
            throw new BoardEditException("a connection needs a source: a gizmo or the outer walls");
        }
        if (source instanceof TriggerSource.OfGizmo gizmo) {
            registry.requireGizmo(gizmo.gizmo());
        }
        GizmoKind kind = registry.requireGizmo(target).kind();
        Connection connection = new Connection(source, target, normal(order, target, kind, kind.defaultAction()));
        if (connections.stream().anyMatch(connection::sameEnds)) {
            throw new BoardEditException("connection " + source + " \u2192 " + target + " already exists");
        }
        connections.add(connection);
        changed();
    }

    void disconnect(TriggerSource source, String target) {
        if (!connections.removeIf(new Connection(source, target)::sameEnds)) {
            throw new BoardEditException("there is no connection " + source + " \u2192 " + target);
        }
        changed();
    }

    void bindKey(int keyCode, KeyEdge edge, String gizmo, Order order) {
        if (keyCode < 0) {
            throw new BoardEditException("key code must be 0 or more, got " + keyCode);
        }
        if (edge == null) {
            throw new BoardEditException("key binding for " + gizmo + " needs an edge, DOWN or UP");
        }
        GizmoKind kind = registry.requireGizmo(gizmo).kind();
        KeyBinding binding = new KeyBinding(keyCode, edge, gizmo, normal(order, gizmo, kind, edge.actionOf(kind)));
        if (keyBindings.stream().anyMatch(binding::sameEdgeOfKey)) {
            throw new BoardEditException("key " + keyCode + " " + edgeName(edge) + " is already bound to " + gizmo);
        }
        keyBindings.add(binding);
    }

    void unbindKey(int keyCode, KeyEdge edge, String gizmo) {
        if (!keyBindings.removeIf(new KeyBinding(keyCode, edge, gizmo)::sameEdgeOfKey)) {
            throw new BoardEditException("key " + keyCode + " " + edgeName(edge) + " is not bound to " + gizmo);
        }
    }

    /**
     * The order as the board keeps it, or the reason it cannot: an action the target's kind has, or empty where it is
     * what the target does unless told ({@code unlessTold}), so that one meaning has one form and a board without
     * actions of its own is written as the standard format has it; a delay of 0 to {@link Order#MAX_DELAY} seconds.
     */
    private static Order normal(Order order, String target, GizmoKind kind, Action unlessTold) {
        if (order == null) {
            throw new BoardEditException("no order given for " + target);
        }
        if (!(order.delay() >= 0 && order.delay() <= Order.MAX_DELAY)) {
            throw new BoardEditException("a delay is 0 to " + (int) Order.MAX_DELAY + " seconds, not " + order.delay());
        }
        if (order.action().isEmpty() || order.action().get() == unlessTold) {
            return new Order(Optional.empty(), order.delay());
        }
        Action action = order.action().get();
        if (!kind.actions().contains(action)) {
            List<String> can = kind.actions().stream().map(Action::word).toList();
            String choices = can.size() == 1 ? can.get(0)
                    : String.join(", ", can.subList(0, can.size() - 1)) + " or " + can.get(can.size() - 1);
            throw new BoardEditException(target + " is " + kind.withArticle() + ", which can " + choices + ", not "
                    + action.word());
        }
        return order;
    }

    /** A deleted gizmo takes its connections, both ways, and its key bindings with it. */
    void forget(String gizmo) {
        connections.removeIf(c -> c.source().equals(TriggerSource.gizmo(gizmo)) || c.target().equals(gizmo));
        changed();
        keyBindings.removeIf(k -> k.gizmo().equals(gizmo));
    }

    private static String edgeName(KeyEdge edge) {
        return edge == null ? "?" : edge.name().toLowerCase(Locale.ROOT);
    }
}
