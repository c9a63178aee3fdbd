package gizmoball.model.gizmo;

/**
 * How an absorber that is a plunger launches: the key that fires it pulls it while held, and its release fires the
 * ball at a speed that grows with the time held up to a full pull,
 * {@code v(t) = MIN_SPEED + (fullSpeed - MIN_SPEED) * min(t, pullSeconds) / pullSeconds}. The time held is the sum of
 * the ticks run while the key was down: the board's clock, so a replay launches at the same speed to the bit.
 *
 * @param fullSpeed   L/s at a full pull (the board checks it lies above {@link #MIN_SPEED} and within its speed limit)
 * @param pullSeconds the seconds of holding that make a full pull ({@link #MIN_PULL_SECONDS} to {@link #MAX_PULL_SECONDS})
 */
public record Plunger(double fullSpeed, double pullSeconds) {
    /** L/s of a release the moment it was pulled: the ball leaves the absorber, no more. */
    public static final double MIN_SPEED = 10;
    /** A full pull launches as a standard absorber fires. */
    public static final double DEFAULT_FULL_SPEED = 50;
    public static final double DEFAULT_PULL_SECONDS = 1;
    public static final double MIN_PULL_SECONDS = 0.1;
    public static final double MAX_PULL_SECONDS = 5;
    public static final Plunger DEFAULT = new Plunger(DEFAULT_FULL_SPEED, DEFAULT_PULL_SECONDS);

    /** How far it is pulled after {@code heldSeconds} of holding: 0 to 1. */
    public double pullAfter(double heldSeconds) {
        return Math.min(heldSeconds, pullSeconds) / pullSeconds;
    }

    /** The launch speed of a release after {@code heldSeconds} of holding, in L/s. */
    public double speedAfter(double heldSeconds) {
        return MIN_SPEED + (fullSpeed - MIN_SPEED) * pullAfter(heldSeconds);
    }
}
