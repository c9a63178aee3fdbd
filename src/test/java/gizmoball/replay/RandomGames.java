package gizmoball.replay;

import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.game.KeyPress;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;

/** Random key scripts for a board: its own keys (and one it does not bind) go down and up at random ticks. */
public final class RandomGames {
    /** A key no board binds: pressing it must change nothing, and a replay must still hold it. */
    private static final int UNBOUND = java.awt.event.KeyEvent.VK_F12;

    private RandomGames() {
    }

    public static KeyScript script(Board board, Random random, long ticks) {
        List<Integer> codes = new ArrayList<>(board.keyBindings().stream().map(KeyBinding::keyCode).distinct().toList());
        codes.add(UNBOUND);
        Set<Integer> down = new HashSet<>();
        List<KeyPress> keys = new ArrayList<>();
        for (long tick = random.nextInt(30); tick < ticks; tick += 1 + random.nextInt(40)) {
            // Now and then two keys at one tick, as a player pressing both flippers at once.
            for (int k = random.nextInt(6) == 0 ? 2 : 1; k > 0; k--) {
                int code = codes.get(random.nextInt(codes.size()));
                boolean press = down.add(code);
                if (!press) {
                    down.remove(code);
                }
                keys.add(new KeyPress(tick, press ? KeyPress.Motion.DOWN : KeyPress.Motion.UP, code));
            }
        }
        return new KeyScript(keys);
    }
}
