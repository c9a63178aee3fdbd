package gizmoball.model.gizmo;

/** What views, controllers and the editor see of a gate: whether it is open, read only. */
public sealed interface GateView extends Gizmo permits Gate {
    /** True while balls pass through it. */
    boolean isOpen();

    /** True while it is open only because a ball lies in its cell: it closes once the cell is clear. */
    boolean isClosing();
}
