package gizmoball.editor;

import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.Order;
import java.util.List;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.TriggerSource;

/**
 * The half-done step of a tool: what the next pointer or key event completes. Exactly one is pending at a time
 * ({@link #NONE} when nothing is), so the editor's state is this value, not a combination of nullable fields.
 */
public sealed interface PendingStep {
    PendingStep NONE = new None();

    /** Nothing half-done: the next press starts something. */
    record None() implements PendingStep { }

    /** Absorber: the button went down on cell (x0, y0); the release gives the opposite corner. */
    record DraggingAbsorber(int x0, int y0) implements PendingStep { }

    /** Ball: its centre is (x, y) (snapped); the drag from (pressX, pressY) gives its velocity. */
    record PlacingBall(double x, double y, double pressX, double pressY) implements PendingStep { }

    /** Select: dragging a gizmo grabbed (grabDx, grabDy) cells from its top-left cell. */
    record MovingGizmo(Gizmo gizmo, int grabDx, int grabDy) implements PendingStep { }

    /** Placing a bumper or flipper: the button went down on cell (x0, y0); a drag fills the rectangle to the pointer. */
    record Filling(int x0, int y0) implements PendingStep { }

    /** Select: a rubber band from (x0, y0) to (x1, y1); {@code adding} (Shift) adds to the selection. */
    record Banding(double x0, double y0, double x1, double y1, boolean adding) implements PendingStep { }

    /** Select: dragging the selected group, grabbed at (pressX, pressY). */
    record MovingGroup(List<String> names, double pressX, double pressY) implements PendingStep {
        public MovingGroup {
            names = List.copyOf(names);
        }
    }

    /**
     * Select: dragging a handle of the absorber; {@code left}, {@code top}, {@code right}, {@code bottom} say which
     * of its edges follow the pointer (two for a corner handle, one for an edge handle).
     */
    record ResizingAbsorber(Gizmo absorber, boolean left, boolean top, boolean right, boolean bottom)
            implements PendingStep { }

    /** Select: dragging a ball grabbed at (pressX, pressY). */
    record MovingBall(BallView ball, double pressX, double pressY) implements PendingStep { }

    /** Connect or Disconnect: the source (a gizmo or the outer walls) is chosen, the target is next. */
    record ConnectingFrom(TriggerSource source) implements PendingStep { }

    /**
     * Connect: source and target are chosen, and the order so far (what the target does when the source is hit,
     * after how long); the answer that makes the connection is next.
     */
    record AwaitingAction(TriggerSource source, String target, Order order) implements PendingStep { }

    /** Key Connect or Key Disconnect: the gizmo is chosen, the key is next. */
    record AwaitingKey(String gizmo) implements PendingStep { }

    /**
     * Key Connect: gizmo and key are chosen, and the order so far (what the binding makes the gizmo do, after how
     * long); on key down, key up, or both, is next.
     */
    record AwaitingEdge(String gizmo, int keyCode, Order order) implements PendingStep {
        /** The gizmo to do as the key drives it, at once, unless the order is changed before the edge is chosen. */
        AwaitingEdge(String gizmo, int keyCode) {
            this(gizmo, keyCode, Order.DEFAULT);
        }
    }

    /** True for the steps of a press that is still held: the pointer's moves are drags of it. */
    default boolean isGesture() {
        return this instanceof DraggingAbsorber || this instanceof PlacingBall || this instanceof MovingGizmo
                || this instanceof MovingBall || this instanceof Filling || this instanceof Banding
                || this instanceof MovingGroup || this instanceof ResizingAbsorber;
    }
}
