package gizmoball.model.game;

/**
 * When nudging tilts a game: the {@code nudges}-th nudge within {@code seconds} of play tilts it, the one before warns.
 * A tilt lowers the flippers and stops them and the plungers answering their keys, and the ball scores nothing more,
 * until it drains (or no ball is left free).
 */
public record Tilt(int nudges, double seconds) {
    public static final int MAX_NUDGES = 20;
    public static final double MAX_SECONDS = 60;
    /** Three nudges within five seconds warn, a fourth tilts. */
    public static final Tilt DEFAULT = new Tilt(4, 5);

    /** @throws IllegalArgumentException with the reason, in words for a board author */
    public Tilt {
        if (nudges < 2 || nudges > MAX_NUDGES) {
            throw new IllegalArgumentException("a tilt comes with the 2nd to " + MAX_NUDGES + "th nudge, not the "
                    + nudges + "th");
        }
        if (!(seconds > 0 && seconds <= MAX_SECONDS)) {
            throw new IllegalArgumentException("a tilt counts the nudges of more than 0 and at most "
                    + (int) MAX_SECONDS + " seconds, not " + seconds);
        }
    }
}
