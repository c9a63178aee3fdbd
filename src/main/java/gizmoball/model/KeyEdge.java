package gizmoball.model;

import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.GizmoKind;

/**
 * What of a key press a key binding reacts to: {@link #DOWN} the press, {@link #UP} the release (a flipper bound
 * to them swings up while the key is held), {@link #CHANGE} the press as a trigger: the gizmo performs its action
 * as when it is hit (a flipper toggles, an absorber fires).
 */
public enum KeyEdge {
    DOWN, UP, CHANGE;

    /** What a binding of this edge makes a gizmo of that kind do unless it says otherwise. */
    public Action actionOf(GizmoKind kind) {
        return switch (this) {
            case DOWN -> kind.pressAction();
            case UP -> kind.releaseAction();
            case CHANGE -> kind.defaultAction();
        };
    }
}
