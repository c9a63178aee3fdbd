package gizmoball.fuzz;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Random key scripts: each key alternately pressed and released over the whole run, held and left for spells whose
 * length is the key's own habit: tapped (1-6 ticks), played (3-40) or held long (30-600).
 */
final class KeyScripts {
    private static final int[][] HABITS = {{1, 6}, {3, 40}, {30, 600}};

    private KeyScripts() {
    }

    static KeyScript random(SplittableRandom random, List<Integer> keys, int ticks) {
        List<KeyScript.Press> presses = new ArrayList<>();
        for (int key : keys) {
            int[] habit = HABITS[random.nextInt(HABITS.length)];
            int tick = 1 + random.nextInt(60);
            boolean down = true;
            while (tick <= ticks) {
                presses.add(new KeyScript.Press(tick, key, down));
                down = !down;
                tick += random.nextInt(habit[0], habit[1] + 1);
            }
        }
        return new KeyScript(presses);
    }
}
