package gizmoball.editor;

import java.util.List;
import java.util.Optional;

/** What the editor would do at the pointer: drawn green when it fits, red (with the reason) when refused. */
public sealed interface Preview {
    /** Why the board would refuse it, or empty when it fits. */
    Optional<String> problem();

    default boolean fits() {
        return problem().isEmpty();
    }

    /** A gizmo footprint of whole cells, top-left cell (x, y). */
    record Footprint(int x, int y, int width, int height, Optional<String> problem) implements Preview { }

    /** A ball centred at (x, y) that would start with velocity (vx, vy). */
    record BallPlacement(double x, double y, double vx, double vy, Optional<String> problem) implements Preview { }

    /**
     * Several at once, fitting or refused together: a group of gizmos and balls being moved ({@code moving} by
     * (dx, dy) L, the parts where they would go), or the gizmos a drag fills a rectangle with ({@code moving} empty,
     * the parts those that fit).
     */
    record Group(List<Preview> parts, List<String> moving, double dx, double dy, Optional<String> problem)
            implements Preview {
        public Group {
            parts = List.copyOf(parts);
            moving = List.copyOf(moving);
        }
    }
}
