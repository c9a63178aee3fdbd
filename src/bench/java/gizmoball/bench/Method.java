package gizmoball.bench;

import java.util.ArrayList;
import java.util.List;

/** One way of stepping a board: a loop at a fixed tick length. */
public record Method(Loop loop, int ticksPerSecond) {

    /** The tick lengths the issue asks for: coarse, the game's default, fine, and Visual Pinball X's 1000 Hz. */
    static final int[] RATES = {20, 60, 240, 1000};

    /** The reference for scenes without a closed form: the most accurate loop at a very small tick. */
    static final Method REFERENCE = new Method(Loop.CONTINUOUS, 4000);

    /** The game's default: whole tick simulated, 60 ticks a second (one per frame). */
    static final Method GAME_DEFAULT = new Method(Loop.CONTINUOUS, 60);

    double dt() {
        return 1.0 / ticksPerSecond;
    }

    String label() {
        return loop + " 1/" + ticksPerSecond;
    }

    static List<Method> all() {
        List<Method> methods = new ArrayList<>();
        for (Loop loop : Loop.values()) {
            for (int rate : RATES) {
                methods.add(new Method(loop, rate));
            }
        }
        return methods;
    }
}
