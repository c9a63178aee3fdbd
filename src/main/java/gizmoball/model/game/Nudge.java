package gizmoball.model.game;

import java.util.Optional;

/**
 * The board's nudge: its three keys push every free ball left, right or up (toward the top of the board) by
 * {@code speed} L/s at once, woken if asleep; held balls feel nothing. Nudging too often tilts the game ({@link Tilt}).
 *
 * @param speed L/s added to each free ball ({@link #MAX_SPEED} at most)
 */
public record Nudge(double speed, int leftKey, int rightKey, int upKey) {
    public static final double DEFAULT_SPEED = 4;
    public static final double MAX_SPEED = 20;
    /** The arrow keys (KeyEvent codes of Left, Right and Up): the shipped boards' flippers and launch use none. */
    public static final Nudge DEFAULT = new Nudge(DEFAULT_SPEED, 37, 39, 38);

    /** Which way a nudge pushes. */
    public enum Way {
        LEFT(-1, 0), RIGHT(1, 0), UP(0, -1);

        private final int dx;
        private final int dy;

        Way(int dx, int dy) {
            this.dx = dx;
            this.dy = dy;
        }

        /** The unit vector's x along the board (y grows downward). */
        public int dx() {
            return dx;
        }

        public int dy() {
            return dy;
        }
    }

    /** @throws IllegalArgumentException with the reason, in words for a board author */
    public Nudge {
        if (!(speed > 0 && speed <= MAX_SPEED)) {
            throw new IllegalArgumentException("a nudge adds more than 0 and at most " + (int) MAX_SPEED
                    + " L/s, not " + speed);
        }
        if (leftKey == rightKey || leftKey == upKey || rightKey == upKey) {
            throw new IllegalArgumentException("a nudge's left, right and up keys are three different keys");
        }
    }

    /** The way the key nudges, if it is one of the nudge's keys. */
    public Optional<Way> wayOf(int keyCode) {
        if (keyCode == leftKey) {
            return Optional.of(Way.LEFT);
        }
        if (keyCode == rightKey) {
            return Optional.of(Way.RIGHT);
        }
        return keyCode == upKey ? Optional.of(Way.UP) : Optional.empty();
    }
}
