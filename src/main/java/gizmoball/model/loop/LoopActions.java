package gizmoball.model.loop;

import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.model.gizmo.MovingShape;

/**
 * What the loop may do to the board beyond moving its balls and moving shapes (docs/design.md, "The tick"): report what
 * happened, trigger the gizmos a hit is connected to, capture a ball, wake what a moving shape's sweep reaches, and move
 * the board's clock on. Its reads go through {@link LoopView}.
 */
public interface LoopActions {
    void recordEvent(PlayEvent event);

    /** {@code ball} hit {@code struck}, as {@link PlayEvent.Hit} has it: its centre is where it is now. */
    void recordHit(Ball ball, Struck struck, GizmoKind kind, double speed);

    /** Stage 6: the events since the last tick's end are this tick's, read in place until the next tick ends. */
    TickEvents closeTickEvents();

    /** The gizmo does what its connection orders (stage 5), {@code now} seconds into play. */
    void trigger(GizmoBase gizmo, Order order, double now);

    /**
     * The gizmo takes the ball ({@link GizmoBase#ballTaking}): an absorber holds it; a sink takes it out of play, and
     * it stops at once and leaves the board when the tick is over.
     */
    void take(Ball ball, GizmoBase gizmo);

    /** Wakes every ball where the moving shape's sweep can reach, and what rests on them. */
    void wakeSweep(MovingShape moving);

    /** Pairs placed on each other that have now separated collide from now on. */
    void forgetSeparatedPairs();

    void advanceTime(double dt);
}
