package gizmoball.fuzz;

import gizmoball.model.Board;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Key presses and releases by tick, in the form the reproductions of issue 20 carry them: comment lines
 * {@code # key T CODE down|up}, each pressing or releasing key CODE before tick T (ticks counted from 1 at load).
 */
public record KeyScript(List<Press> presses) {

    /** Key {@code code} goes down ({@code down}) or up before tick {@code tick}. */
    public record Press(int tick, int code, boolean down) {
        String line() {
            return String.format(Locale.ROOT, "# key %d %d %s", tick, code, down ? "down" : "up");
        }
    }

    private static final Pattern LINE = Pattern.compile("#\\s*key\\s+(\\d+)\\s+(\\d+)\\s+(down|up)\\s*");

    /** Sorted by tick; presses of one tick keep their order. */
    public KeyScript {
        presses = presses.stream().sorted(Comparator.comparingInt(Press::tick)).toList();
    }

    /** The {@code # key} lines of a board file's text, in order; other lines are ignored. */
    public static KeyScript fromComments(String text) {
        List<Press> presses = new ArrayList<>();
        for (String line : text.split("\n", -1)) {
            Matcher m = LINE.matcher(line.strip());
            if (m.matches()) {
                presses.add(new Press(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)),
                        m.group(3).equals("down")));
            }
        }
        return new KeyScript(presses);
    }

    /** The script as comment lines, one press each, ending with a newline (empty for no presses). */
    public String toComments() {
        StringBuilder text = new StringBuilder();
        presses.forEach(p -> text.append(p.line()).append('\n'));
        return text.toString();
    }

    /** A cursor that plays the script along a run: call {@link Player#beforeTick} before every tick. */
    public Player player() {
        return new Player();
    }

    /** Presses the keys due before each tick. */
    public final class Player {
        private int next;

        private Player() {
        }

        /** Sends the board every press due before tick {@code tick} (counted from 1). */
        public void beforeTick(Board board, int tick) {
            while (next < presses.size() && presses.get(next).tick() <= tick) {
                Press press = presses.get(next++);
                if (press.down()) {
                    board.keyDown(press.code());
                } else {
                    board.keyUp(press.code());
                }
            }
        }
    }
}
