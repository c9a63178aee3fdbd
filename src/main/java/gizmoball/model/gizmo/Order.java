package gizmoball.model.gizmo;

import java.util.Optional;

/**
 * What a connection or a key binding tells its target: an action, or empty for what the target does unless told
 * (its kind's default for a trigger, its press or release action for a key), and how many seconds of the board's
 * clock after the trigger or key it does it (0: at once; otherwise at the first tick boundary the delay has
 * reached, before the next tick runs: simulated time, so replays, slow motion and the headless runner agree).
 */
public record Order(Optional<Action> action, double delay) {
    /** The target's own action, at once: what every connection and binding of the standard format means. */
    public static final Order DEFAULT = new Order(Optional.empty(), 0);
    /** The longest delay: an hour of play. */
    public static final double MAX_DELAY = 3600;

    public Order {
        if (action == null) {
            throw new IllegalArgumentException("an order's action is empty or an action, never null");
        }
    }

    /** {@code action} at once. */
    public static Order of(Action action) {
        return new Order(Optional.of(action), 0);
    }

    /** The same action after {@code seconds}. */
    public Order after(double seconds) {
        return new Order(action, seconds);
    }

    /** True for the target's own action at once (a line of the standard format). */
    public boolean isDefault() {
        return equals(DEFAULT);
    }
}
