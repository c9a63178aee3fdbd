package gizmoball.model.loop;

import physics.Vect;

/**
 * One free ball at the end of a tick, for the physics overlay.
 *
 * @param nextCollisionIn seconds until its next collision as things stand (infinite if none within the look-ahead)
 * @param nextCollisionAt where its centre will be then (null if none)
 */
public record BallReport(String name, Vect position, Vect velocity, BallState state, double nextCollisionIn,
                         Vect nextCollisionAt) {

    /** How the loop treats a ball: flying freely, in persistent contact with a surface, or asleep. */
    public enum BallState { FLYING, CONTACT, ASLEEP }
}
