package gizmoball.model.gizmo;

/** What views, controllers and the editor see of a drop target: whether it is down, read only. */
public sealed interface DropTargetView extends Gizmo permits DropTarget {
    /** True from the end of the tick a ball hit it until it rises: balls pass through its cell. */
    boolean isDown();

    /** True while it is down only because a ball lies in its cell: it rises once the cell is clear. */
    boolean isRising();
}
