package gizmoball.model.loop;

/** The six stages of a tick, in the order they run (docs/design.md, "The tick"). */
public enum Stage {
    FRICTION_AND_GRAVITY, BALL_MOTION, COLLISION_DETECTION, COLLISION_RESOLUTION, TRIGGERING, REDRAWING
}
