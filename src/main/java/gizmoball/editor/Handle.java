package gizmoball.editor;

import gizmoball.model.gizmo.Gizmo;
import java.util.ArrayList;
import java.util.List;

/**
 * A handle of the selected absorber, at (x, y) in L: its corners and the middles of its edges. Dragging one moves
 * the edges it names ({@code left}, {@code top}, {@code right}, {@code bottom}) to the grid line nearest the pointer.
 */
public record Handle(double x, double y, boolean left, boolean top, boolean right, boolean bottom) {
    /** How near (in L, along each axis) a press must be to a handle to grab it. */
    static final double GRAB = 0.35;

    /** The eight handles of an absorber, corners first. */
    static List<Handle> of(Gizmo absorber) {
        double x0 = absorber.x();
        double y0 = absorber.y();
        double x1 = x0 + absorber.width();
        double y1 = y0 + absorber.height();
        double mx = (x0 + x1) / 2;
        double my = (y0 + y1) / 2;
        List<Handle> handles = new ArrayList<>();
        handles.add(new Handle(x0, y0, true, true, false, false));
        handles.add(new Handle(x1, y0, false, true, true, false));
        handles.add(new Handle(x0, y1, true, false, false, true));
        handles.add(new Handle(x1, y1, false, false, true, true));
        handles.add(new Handle(mx, y0, false, true, false, false));
        handles.add(new Handle(mx, y1, false, false, false, true));
        handles.add(new Handle(x0, my, true, false, false, false));
        handles.add(new Handle(x1, my, false, false, true, false));
        return handles;
    }

    boolean grabbedAt(double px, double py) {
        return Math.abs(px - x) <= GRAB && Math.abs(py - y) <= GRAB;
    }
}
