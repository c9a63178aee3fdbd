package gizmoball.headless;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.List;

/** The values of the headless runner's options, each read or refused with what is expected. */
final class OptionValues {
    private OptionValues() {
    }

    static String of(List<String> args, int index, String option) throws HeadlessOptions.BadArguments {
        if (index >= args.size()) {
            throw new HeadlessOptions.BadArguments(option + " needs a value");
        }
        return args.get(index);
    }

    static long ticks(String value) throws HeadlessOptions.BadArguments {
        try {
            long ticks = Long.parseLong(value);
            if (ticks >= 0) {
                return ticks;
            }
        } catch (NumberFormatException e) {
            // falls through to the message below, which says what is expected
        }
        throw new HeadlessOptions.BadArguments("--ticks needs a whole number >= 0, not '" + value + "'");
    }

    static double dt(String value) throws HeadlessOptions.BadArguments {
        try {
            double dt = Double.parseDouble(value);
            if (Double.isFinite(dt) && dt > 0) {
                return dt;
            }
        } catch (NumberFormatException e) {
            // falls through to the message below, which says what is expected
        }
        throw new HeadlessOptions.BadArguments("--dt needs a number of seconds > 0, not '" + value + "'");
    }

    static Path path(String value) throws HeadlessOptions.BadArguments {
        try {
            return Path.of(value);
        } catch (InvalidPathException e) {
            throw new HeadlessOptions.BadArguments("not a file name: " + value);
        }
    }
}
