package gizmoball.boardfile;

import gizmoball.model.Board;
import gizmoball.model.game.Nudge;
import gizmoball.model.game.Tilt;
import java.util.List;
import java.util.OptionalDouble;
import java.util.OptionalInt;

/**
 * The arguments of board-file commands, one word at a time: numbers, whole numbers, cells, ball coordinates, colour
 * channels, key codes and names, directions; each read or refused with a reason that names what it was for.
 */
final class ArgumentWords {
    /** Far beyond the board, yet safe to turn into an int: larger whole numbers are refused as outside. */
    private static final double COORDINATE_LIMIT = 1_000_000;
    /** A coordinate this far out is no off-by-one: the writer counted pixels, not cells. */
    private static final double PIXEL_COORDINATES_FROM = 2 * Board.SIZE;

    private ArgumentWords() {
    }

    /** A flipper's direction: up (true) or down. */
    static boolean direction(String word) throws Refusal {
        return either(word, "up", "down", "a flipper's direction is up or down");
    }

    /** A spinner running (true) or stopped. */
    static boolean running(String word) throws Refusal {
        return either(word, "running", "stopped", "a spinner is running or stopped");
    }

    /** True for the word {@code yes}, false for {@code no} (in any case); else refused: "{@code what}, not WORD". */
    private static boolean either(String word, String yes, String no, String what) throws Refusal {
        if (word.equalsIgnoreCase(yes)) {
            return true;
        }
        if (word.equalsIgnoreCase(no)) {
            return false;
        }
        throw new Refusal(what + ", not " + word);
    }

    static int channel(String what, String word) throws Refusal {
        int value = wholeNumber(what, word);
        if (value < 0 || value > 255) {
            throw new Refusal(what + " " + word + " is not a colour channel 0..255");
        }
        return value;
    }

    /** A KeyEvent code, or a KeyEvent key name (Space, "Left", q), quoted or not. */
    static int keyCode(String word, List<String> notes) throws Refusal {
        String unquoted = word.length() >= 2 && (word.startsWith("\"") && word.endsWith("\"")
                || word.startsWith("'") && word.endsWith("'")) ? word.substring(1, word.length() - 1) : word;
        if (Decimals.parse(unquoted).isEmpty()) {
            OptionalInt named = KeyCodes.named(unquoted);
            if (named.isEmpty()) {
                throw new Refusal("unknown key " + word + ": neither a key code nor a java.awt.event.KeyEvent key"
                        + " name (VK_ without the prefix, such as Space or Q)");
            }
            notes.add("key " + word + " read as key code " + named.getAsInt());
            return named.getAsInt();
        }
        int keyCode = wholeNumber("key code", unquoted);
        if (!KeyCodes.isKnown(keyCode)) {
            throw new Refusal("unknown key code " + keyCode + " (not a java.awt.event.KeyEvent VK_ code)");
        }
        return keyCode;
    }

    /** A gizmo coordinate: a whole number of cells, also when written as a decimal such as 7.0. */
    static int cell(String what, String word) throws Refusal {
        double value = number(what, word);
        if (value != Math.rint(value)) {
            throw new Refusal(what + " coordinate " + word + " is not a whole cell: gizmos sit on whole cells, the"
                    + " format has no fractional cells");
        }
        if (Math.abs(value) > COORDINATE_LIMIT) {
            throw new Refusal(what + " coordinate " + word + " is outside the board");
        }
        refusePixels(what, word, value);
        return (int) value;
    }

    static double ballCoordinate(String what, String word) throws Refusal {
        double value = number(what, word);
        refusePixels(what, word, value);
        return value;
    }

    static void refusePixels(String what, String word, double value) throws Refusal {
        if (Math.abs(value) >= PIXEL_COORDINATES_FROM && Math.abs(value) <= COORDINATE_LIMIT) {
            throw new Refusal(what + " coordinate " + word + " is far outside the " + Board.SIZE + "x" + Board.SIZE
                    + " board: pixel coordinates, it seems, but the format counts in L (cells)");
        }
    }

    static Nudge nudge(List<String> args, List<String> notes) throws Refusal {
        try {
            return new Nudge(number("nudge speed", args.get(0)), keyCode(args.get(1), notes),
                    keyCode(args.get(2), notes), keyCode(args.get(3), notes));
        } catch (IllegalArgumentException refused) {
            throw new Refusal(refused.getMessage());
        }
    }

    static Tilt tilt(List<String> args) throws Refusal {
        try {
            return new Tilt(wholeNumber("nudges", args.get(0)), number("seconds", args.get(1)));
        } catch (IllegalArgumentException refused) {
            throw new Refusal(refused.getMessage());
        }
    }

    /** A score: a whole number, up to far more than any game reaches. */
    static long score(String word) throws Refusal {
        double value = number("score", word);
        if (value != Math.rint(value) || Math.abs(value) > 1e15) {
            throw new Refusal("score " + word + " is not a whole number");
        }
        return (long) value;
    }

    static int wholeNumber(String what, String word) throws Refusal {
        double value = number(what, word);
        if (value != Math.rint(value) || Math.abs(value) > Integer.MAX_VALUE) {
            throw new Refusal(what + " " + word + " is not a whole number");
        }
        return (int) value;
    }

    static double number(String what, String word) throws Refusal {
        OptionalDouble value = Decimals.parse(word);
        if (value.isEmpty()) {
            throw new Refusal(what + " '" + word + "' is not a number");
        }
        return value.getAsDouble();
    }
}
