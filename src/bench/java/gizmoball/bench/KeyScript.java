package gizmoball.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Timed key presses for a scene, read from a text file of lines {@code <seconds> down|up <keyCode>}
 * ({@code #} starts a comment). An event fires before the first tick that starts at or after its time;
 * the scripts use multiples of 0.05 s so that every tick length of the benchmark hits them exactly.
 */
public final class KeyScript {

    /** One press or release. */
    public record KeyEvent(double time, boolean down, int keyCode) {}

    public static final KeyScript NONE = new KeyScript(List.of());

    private final List<KeyEvent> events;

    public KeyScript(List<KeyEvent> events) {
        this.events = List.copyOf(events);
    }

    public static KeyScript read(Path file) throws IOException {
        List<KeyEvent> events = new ArrayList<>();
        List<String> lines = Files.readAllLines(file);
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i).replaceAll("#.*", "").trim();
            if (line.isEmpty()) {
                continue;
            }
            String[] words = line.split("\\s+");
            if (words.length != 3 || !(words[1].equals("down") || words[1].equals("up"))) {
                throw new IOException(file + ":" + (i + 1) + ": expected '<seconds> down|up <keyCode>' in: " + lines.get(i));
            }
            try {
                events.add(new KeyEvent(Double.parseDouble(words[0]), words[1].equals("down"), Integer.parseInt(words[2])));
            } catch (NumberFormatException e) {
                throw new IOException(file + ":" + (i + 1) + ": not a number in: " + lines.get(i), e);
            }
        }
        return new KeyScript(events);
    }

    /** Plays the script along a run: call {@link Player#beforeTick} with the tick index before every tick. */
    public Player player(double dt) {
        return new Player(dt);
    }

    /** A cursor over the events for one run at one tick length. */
    public final class Player {
        private final double dt;
        private int next;

        private Player(double dt) {
            this.dt = dt;
        }

        void beforeTick(Stepper stepper, long tick) {
            // Compare in whole ticks, so that accumulated floating-point time cannot shift an event by one tick.
            while (next < events.size() && Math.round(events.get(next).time() / dt) <= tick) {
                KeyEvent e = events.get(next++);
                if (e.down()) {
                    stepper.keyDown(e.keyCode());
                } else {
                    stepper.keyUp(e.keyCode());
                }
            }
        }
    }
}
