package gizmoball.editor;

import gizmoball.model.KeyEdge;
import java.util.EnumSet;
import java.util.Set;

/** Key Connect's last answer: the gizmo acts on key down, on key up, or on both (a flipper held up). */
public enum EdgeChoice {
    DOWN(EnumSet.of(KeyEdge.DOWN)),
    UP(EnumSet.of(KeyEdge.UP)),
    DOWN_AND_UP(EnumSet.of(KeyEdge.DOWN, KeyEdge.UP));

    private final Set<KeyEdge> edges;

    EdgeChoice(Set<KeyEdge> edges) {
        this.edges = edges;
    }

    public Set<KeyEdge> edges() {
        return EnumSet.copyOf(edges);
    }
}
