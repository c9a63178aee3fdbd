package gizmoball.model.gizmo;

/**
 * What a gizmo does with a ball that touches it, asked of the gizmo ({@link GizmoBase#ballTaking}) by the loop and
 * the board rather than which kind it is: most bounce it; one that takes it stops it where it says
 * ({@link GizmoBase#take}), and what touches it is never a contact.
 */
public enum BallTaking {
    /** It bounces the ball, or the ball passes through. */
    NONE,
    /** It holds the ball at rest until it fires it (an absorber): the ball stays on the board. */
    HOLDS,
    /**
     * It takes the ball out of play (a sink), even one that only touches it when a tick begins: the ball stops where
     * the gizmo says and leaves the board when the tick is over.
     */
    REMOVES
}
