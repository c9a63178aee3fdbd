package gizmoball.headless;

import gizmoball.model.game.Game;
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
        return seconds(value, "--dt");
    }

    /** A whole number of at least 1: of games, of threads. */
    static int players(String value) throws HeadlessOptions.BadArguments {
        int players = count(value, "--players");
        if (players > Game.MAX_PLAYERS) {
            throw new HeadlessOptions.BadArguments("--players needs 1 to " + Game.MAX_PLAYERS + ", not " + players);
        }
        return players;
    }

    static int count(String value, String option) throws HeadlessOptions.BadArguments {
        try {
            int count = Integer.parseInt(value);
            if (count >= 1) {
                return count;
            }
        } catch (NumberFormatException e) {
            // falls through to the message below, which says what is expected
        }
        throw new HeadlessOptions.BadArguments(option + " needs a whole number >= 1, not '" + value + "'");
    }

    /** A number of seconds > 0. */
    static double seconds(String value, String option) throws HeadlessOptions.BadArguments {
        try {
            double seconds = Double.parseDouble(value);
            if (Double.isFinite(seconds) && seconds > 0) {
                return seconds;
            }
        } catch (NumberFormatException e) {
            // falls through to the message below, which says what is expected
        }
        throw new HeadlessOptions.BadArguments(option + " needs a number of seconds > 0, not '" + value + "'");
    }

    static Path path(String value) throws HeadlessOptions.BadArguments {
        try {
            return Path.of(value);
        } catch (InvalidPathException e) {
            throw new HeadlessOptions.BadArguments("not a file name: " + value);
        }
    }
}
