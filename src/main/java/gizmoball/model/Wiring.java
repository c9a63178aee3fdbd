package gizmoball.model;

import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** What drives which gizmo: the connections from trigger sources and the key bindings, in the order made. */
final class Wiring {
    private final Registry registry;
    private final List<Connection> connections = new ArrayList<>();
    private final List<KeyBinding> keyBindings = new ArrayList<>();

    Wiring(Registry registry) {
        this.registry = registry;
    }

    void copyFrom(Wiring source) {
        clear();
        connections.addAll(source.connections);
        keyBindings.addAll(source.keyBindings);
    }

    void clear() {
        connections.clear();
        keyBindings.clear();
    }

    List<Connection> connections() {
        return List.copyOf(connections);
    }

    List<KeyBinding> keyBindings() {
        return List.copyOf(keyBindings);
    }

    void connect(TriggerSource source, String target) {
        if (source == null) {
            throw new BoardEditException("a connection needs a source: a gizmo or the outer walls");
        }
        if (source instanceof TriggerSource.OfGizmo gizmo) {
            registry.requireGizmo(gizmo.gizmo());
        }
        registry.requireGizmo(target);
        Connection connection = new Connection(source, target);
        if (connections.contains(connection)) {
            throw new BoardEditException("connection " + source + " \u2192 " + target + " already exists");
        }
        connections.add(connection);
    }

    void disconnect(TriggerSource source, String target) {
        if (!connections.remove(new Connection(source, target))) {
            throw new BoardEditException("there is no connection " + source + " \u2192 " + target);
        }
    }

    void bindKey(int keyCode, KeyEdge edge, String gizmo) {
        if (keyCode < 0) {
            throw new BoardEditException("key code must be 0 or more, got " + keyCode);
        }
        if (edge == null) {
            throw new BoardEditException("key binding for " + gizmo + " needs an edge, DOWN or UP");
        }
        registry.requireGizmo(gizmo);
        KeyBinding binding = new KeyBinding(keyCode, edge, gizmo);
        if (keyBindings.contains(binding)) {
            throw new BoardEditException("key " + keyCode + " " + edgeName(edge) + " is already bound to " + gizmo);
        }
        keyBindings.add(binding);
    }

    void unbindKey(int keyCode, KeyEdge edge, String gizmo) {
        if (!keyBindings.remove(new KeyBinding(keyCode, edge, gizmo))) {
            throw new BoardEditException("key " + keyCode + " " + edgeName(edge) + " is not bound to " + gizmo);
        }
    }

    /** A deleted gizmo takes its connections, both ways, and its key bindings with it. */
    void forget(String gizmo) {
        connections.removeIf(c -> c.source().equals(TriggerSource.gizmo(gizmo)) || c.target().equals(gizmo));
        keyBindings.removeIf(k -> k.gizmo().equals(gizmo));
    }

    private static String edgeName(KeyEdge edge) {
        return edge == null ? "?" : edge.name().toLowerCase(Locale.ROOT);
    }
}
