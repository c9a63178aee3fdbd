package gizmoball.lab;

import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.gizmo.BallTaking;
import gizmoball.model.gizmo.Gizmo;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * The launching hand both players share: when an absorber that a key fires holds a ball, it waits a moment, then
 * holds that key for a random time and lets go. A plunger launches faster the longer its key is held, so the random
 * hold gives each ball another launch; an absorber that fires on the press does not care how long it is held.
 */
final class Launcher {
    /** Seconds between seeing a ball waiting and pressing its key. */
    static final double MIN_WAIT = 0.2;
    static final double MAX_WAIT = 1.0;
    /** Seconds the launch key is held. */
    static final double MIN_HOLD = 0.1;
    static final double MAX_HOLD = 1.5;

    /** A gizmo that holds balls (an absorber) and the key that fires it. */
    private record LaunchKey(int keyCode, Gizmo absorber) {
    }

    private final List<LaunchKey> keys = new ArrayList<>();
    private final SplittableRandom random;
    private final double dt;
    /** The key pressed or about to be, else null. */
    private LaunchKey key;
    private long pressAt;
    private long releaseAt;
    private boolean held;

    Launcher(Board board, double dt, SplittableRandom random) {
        this.dt = dt;
        this.random = random;
        for (KeyBinding binding : board.keyBindings()) {
            Gizmo gizmo = board.gizmo(binding.gizmo()).orElse(null);
            if (gizmo != null && gizmo.kind().ballTaking() == BallTaking.HOLDS
                    && keys.stream().noneMatch(k -> k.absorber() == gizmo)) {
                keys.add(new LaunchKey(binding.keyCode(), gizmo));
            }
        }
    }

    void beforeTick(Board board) {
        long now = board.ticks();
        if (held) {
            if (now >= releaseAt) {
                board.keyUp(key.keyCode());
                held = false;
                key = null;
            }
        } else if (key != null) {
            if (now >= pressAt) {
                board.keyDown(key.keyCode());
                held = true;
                releaseAt = now + ticks(MIN_HOLD, MAX_HOLD);
            }
        } else {
            for (LaunchKey waiting : keys) {
                if (!waiting.absorber().held().isEmpty()) {
                    key = waiting;
                    pressAt = now + ticks(MIN_WAIT, MAX_WAIT);
                    return;
                }
            }
        }
    }

    /** A random whole number of ticks between the two times, in seconds; at least one. */
    private long ticks(double fromSeconds, double toSeconds) {
        double seconds = fromSeconds + random.nextDouble() * (toSeconds - fromSeconds);
        return Math.max(1, Math.round(seconds / dt));
    }
}
