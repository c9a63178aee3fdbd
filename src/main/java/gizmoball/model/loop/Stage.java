package gizmoball.model.loop;

/**
 * The six stages of a tick in the order they run (docs/design.md, "The tick"), each with its number in the product
 * description (docs/rules.md, "The tick"). A tick detects the next collision before it moves anything to it, so
 * stage 3 runs before stage 2; then the two take turns with 4 and 5 until the tick is used up.
 */
public enum Stage {
    FRICTION_AND_GRAVITY(1), COLLISION_DETECTION(3), BALL_MOTION(2), COLLISION_RESOLUTION(4), TRIGGERING(5),
    REDRAWING(6);

    private final int number;

    Stage(int number) {
        this.number = number;
    }

    /** Its number in the product description's list of the stages (docs/rules.md, "The tick"). */
    public int number() {
        return number;
    }
}
