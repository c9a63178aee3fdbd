package gizmoball.replay;

import gizmoball.boardfile.KeyCodes;
import gizmoball.model.game.KeyPress;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.OptionalInt;
import java.util.stream.Collectors;

/**
 * Key presses and releases with their ticks, in the order they happen. As text (the headless runner's
 * {@code --keys} file): one event a line, {@code tick down|up key}, the key a {@code KeyEvent} code or name
 * ({@code 32}, {@code Space}, {@code VK_Z}); blank lines and {@code #} comment lines are skipped; ticks never go back.
 * A key at tick n goes down (or up) after n ticks, so it acts in tick n + 1.
 */
public record KeyScript(List<KeyPress> keys) {
    public static final KeyScript NONE = new KeyScript(List.of());

    /** @throws IllegalArgumentException if the ticks go back */
    public KeyScript {
        keys = List.copyOf(keys);
        for (int i = 1; i < keys.size(); i++) {
            if (keys.get(i).tick() < keys.get(i - 1).tick()) {
                throw new IllegalArgumentException("key presses out of order: tick " + keys.get(i).tick()
                        + " after tick " + keys.get(i - 1).tick());
            }
        }
    }

    /** A script that is not one; the message names the source, the line and the reason. */
    public static final class BadScript extends Exception {
        private static final long serialVersionUID = 1L;

        BadScript(String message) {
            super(message);
        }
    }

    /** @param source names the script in messages (its file) */
    public static KeyScript parse(String source, String text) throws BadScript {
        List<KeyPress> keys = new ArrayList<>();
        String[] lines = text.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            try {
                KeyPress key = parseLine(line);
                if (!keys.isEmpty() && key.tick() < keys.get(keys.size() - 1).tick()) {
                    throw new BadScript("tick " + key.tick() + " comes before the tick of the line above, "
                            + keys.get(keys.size() - 1).tick());
                }
                keys.add(key);
            } catch (BadScript bad) {
                throw new BadScript(source + ":" + (i + 1) + ": " + bad.getMessage() + ": " + line);
            }
        }
        return new KeyScript(keys);
    }

    private static KeyPress parseLine(String line) throws BadScript {
        String[] words = line.split("\\s+");
        if (words.length != 3) {
            throw new BadScript("expected three words, tick down|up key, found " + words.length);
        }
        long tick;
        try {
            tick = Long.parseLong(words[0]);
        } catch (NumberFormatException e) {
            throw new BadScript("the tick '" + words[0] + "' is not a whole number");
        }
        if (tick < 0) {
            throw new BadScript("the tick " + tick + " is negative");
        }
        KeyPress.Motion motion = switch (words[1].toLowerCase(Locale.ROOT)) {
            case "down" -> KeyPress.Motion.DOWN;
            case "up" -> KeyPress.Motion.UP;
            default -> throw new BadScript("a key goes down or up, not '" + words[1] + "'");
        };
        return new KeyPress(tick, motion, keyCode(words[2]));
    }

    private static int keyCode(String word) throws BadScript {
        try {
            int code = Integer.parseInt(word);
            if (KeyCodes.isKnown(code)) {
                return code;
            }
            throw new BadScript("unknown key code " + code + " (not a java.awt.event.KeyEvent VK_ code)");
        } catch (NumberFormatException notANumber) {
            OptionalInt named = KeyCodes.named(word);
            if (named.isEmpty()) {
                throw new BadScript("unknown key " + word + ": neither a key code nor a java.awt.event.KeyEvent key"
                        + " name (VK_ without the prefix, such as Space or Z)");
            }
            return named.getAsInt();
        }
    }

    /** The text form, which {@link #parse} reads back to an equal script. */
    public String toText() {
        return keys.stream().map(k -> k.tick() + " " + k.motion().name().toLowerCase(Locale.ROOT) + " " + k.keyCode())
                .collect(Collectors.joining("\n", "", keys.isEmpty() ? "" : "\n"));
    }
}
