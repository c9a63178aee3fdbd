package gizmoball.boardfile;

import gizmoball.model.KeyEdge;
import java.util.List;
import java.util.Locale;
import java.util.OptionalDouble;

/** Turns one command line into a {@link Command}, or says precisely why it cannot. */
final class CommandParser {
    /** Far beyond the board, yet safe to turn into an int: larger whole numbers are refused as outside. */
    private static final double COORDINATE_LIMIT = 1_000_000;

    private CommandParser() {
    }

    /** Thrown for a line that is not a well-formed command; the message is the reason. */
    static final class Refusal extends Exception {
        private static final long serialVersionUID = 1L;

        Refusal(String reason) {
            super(reason);
        }
    }

    static Command parse(String line) throws Refusal {
        List<String> words = BoardFileLexer.words(line);
        CommandWord word = CommandWord.lookup(words.get(0))
                .orElseThrow(() -> new Refusal("unknown command '" + words.get(0) + "'"));
        List<String> args = words.subList(1, words.size());
        if (args.size() != word.argumentCount()) {
            throw new Refusal("wrong number of arguments: " + word.spelling() + " takes " + word.argumentCount()
                    + " (" + word.usage() + "), found " + args.size());
        }
        return switch (word) {
            case SQUARE, CIRCLE, TRIANGLE, LEFT_FLIPPER, RIGHT_FLIPPER -> new Command.AddGizmo(word.kind(),
                    args.get(0), cell("x", args.get(1)), cell("y", args.get(2)));
            case ABSORBER -> new Command.AddAbsorber(args.get(0), cell("x1", args.get(1)), cell("y1", args.get(2)),
                    cell("x2", args.get(3)), cell("y2", args.get(4)));
            case BALL -> new Command.AddBall(args.get(0), number("x", args.get(1)), number("y", args.get(2)),
                    number("vx", args.get(3)), number("vy", args.get(4)));
            case ROTATE -> new Command.Rotate(args.get(0));
            case DELETE -> new Command.Delete(args.get(0));
            case MOVE -> new Command.Move(args.get(0), number("x", args.get(1)), number("y", args.get(2)));
            case CONNECT -> new Command.Connect(args.get(0), args.get(1));
            case KEY_CONNECT -> keyConnect(args);
            case GRAVITY -> new Command.Gravity(number("gravity", args.get(0)));
            case FRICTION -> new Command.Friction(number("mu", args.get(0)), number("mu2", args.get(1)));
        };
    }

    private static Command keyConnect(List<String> args) throws Refusal {
        if (!args.get(0).equalsIgnoreCase("key")) {
            throw new Refusal("expected the word 'key' after KeyConnect, found '" + args.get(0) + "'");
        }
        int keyCode = wholeNumber("key code", args.get(1));
        if (!KeyCodes.isKnown(keyCode)) {
            throw new Refusal("unknown key code " + keyCode + " (not a java.awt.event.KeyEvent VK_ code)");
        }
        KeyEdge edge = switch (args.get(2).toLowerCase(Locale.ROOT)) {
            case "down" -> KeyEdge.DOWN;
            case "up" -> KeyEdge.UP;
            default -> throw new Refusal("bad direction '" + args.get(2) + "': expected down or up");
        };
        return new Command.KeyConnect(keyCode, edge, args.get(3));
    }

    /** A gizmo coordinate: a whole number of cells, also when written as a decimal such as 7.0. */
    private static int cell(String what, String word) throws Refusal {
        double value = number(what, word);
        if (value != Math.rint(value)) {
            throw new Refusal(what + " coordinate " + word + " is not a whole cell");
        }
        if (Math.abs(value) > COORDINATE_LIMIT) {
            throw new Refusal(what + " coordinate " + word + " is outside the board");
        }
        return (int) value;
    }

    private static int wholeNumber(String what, String word) throws Refusal {
        double value = number(what, word);
        if (value != Math.rint(value) || Math.abs(value) > Integer.MAX_VALUE) {
            throw new Refusal(what + " " + word + " is not a whole number");
        }
        return (int) value;
    }

    private static double number(String what, String word) throws Refusal {
        OptionalDouble value = Decimals.parse(word);
        if (value.isEmpty()) {
            throw new Refusal(what + " '" + word + "' is not a number");
        }
        return value.getAsDouble();
    }
}
