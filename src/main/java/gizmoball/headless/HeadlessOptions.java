package gizmoball.headless;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

/**
 * The command line of the headless runner:
 * {@code --headless --ticks N [--dt SECONDS] [--skip-bad-lines] [--out FILE] BOARD}, options in any order.
 *
 * @param dt empty: the model's default tick
 */
public record HeadlessOptions(Path board, long ticks, Optional<Double> dt, boolean skipBadLines, Optional<Path> out) {

    public static final String USAGE =
            "usage: gizmoball --headless --ticks N [--dt SECONDS] [--skip-bad-lines] [--out FILE] BOARD";

    /** The command line is not one the runner understands; the message says why. */
    public static final class BadArguments extends Exception {
        private static final long serialVersionUID = 1L;

        BadArguments(String message) {
            super(message);
        }
    }

    public static HeadlessOptions parse(List<String> args) throws BadArguments {
        Long ticks = null;
        Optional<Double> dt = Optional.empty();
        boolean skipBadLines = false;
        Optional<Path> out = Optional.empty();
        Path board = null;
        for (int i = 0; i < args.size(); i++) {
            String arg = args.get(i);
            switch (arg) {
                case "--headless" -> { }
                case "--ticks" -> ticks = ticks(valueOf(args, ++i, arg));
                case "--dt" -> dt = Optional.of(dt(valueOf(args, ++i, arg)));
                case "--skip-bad-lines" -> skipBadLines = true;
                case "--out" -> out = Optional.of(path(valueOf(args, ++i, arg)));
                default -> {
                    // "-" alone would be a file name; anything else with a dash is an option, never a board.
                    if (arg.startsWith("-") && arg.length() > 1) {
                        throw new BadArguments("unknown option " + arg);
                    }
                    if (board != null) {
                        throw new BadArguments("more than one board file: " + board + " and " + arg);
                    }
                    board = path(arg);
                }
            }
        }
        if (ticks == null) {
            throw new BadArguments("--ticks N is required");
        }
        if (board == null) {
            throw new BadArguments("no board file given");
        }
        return new HeadlessOptions(board, ticks, dt, skipBadLines, out);
    }

    private static String valueOf(List<String> args, int index, String option) throws BadArguments {
        if (index >= args.size()) {
            throw new BadArguments(option + " needs a value");
        }
        return args.get(index);
    }

    private static long ticks(String value) throws BadArguments {
        try {
            long ticks = Long.parseLong(value);
            if (ticks >= 0) {
                return ticks;
            }
        } catch (NumberFormatException e) {
            // falls through to the message below, which says what is expected
        }
        throw new BadArguments("--ticks needs a whole number >= 0, not '" + value + "'");
    }

    private static double dt(String value) throws BadArguments {
        try {
            double dt = Double.parseDouble(value);
            if (Double.isFinite(dt) && dt > 0) {
                return dt;
            }
        } catch (NumberFormatException e) {
            // falls through to the message below, which says what is expected
        }
        throw new BadArguments("--dt needs a number of seconds > 0, not '" + value + "'");
    }

    private static Path path(String value) throws BadArguments {
        try {
            return Path.of(value);
        } catch (InvalidPathException e) {
            throw new BadArguments("not a file name: " + value);
        }
    }
}
