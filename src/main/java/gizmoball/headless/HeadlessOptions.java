package gizmoball.headless;

import gizmoball.lab.LabSettings;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

/**
 * The command line of the headless runner, options in any order: a {@link Play} of a board for N ticks (to a key
 * script, with a report and a replay file if asked), a {@link Check} of a replay file, or a {@link Lab} of a board.
 */
public sealed interface HeadlessOptions {

    String PLAY_USAGE = "gizmoball --headless --ticks N [--dt SECONDS] [--skip-bad-lines] [--out FILE] [--keys SCRIPT]"
            + " [--players N] [--report FILE] [--record FILE] BOARD";
    String CHECK_USAGE = "gizmoball --headless --replay FILE [--report FILE]";
    String LAB_USAGE = "gizmoball --headless --lab N [--threads N] [--game-cap SECONDS] [--skip-bad-lines]"
            + " [--report FILE] [--heatmap FILE.png] BOARD";
    String USAGE = "usage: " + PLAY_USAGE + System.lineSeparator() + "       " + CHECK_USAGE
            + System.lineSeparator() + "       " + LAB_USAGE;

    /** Where to write the game's JSON summary, if anywhere. */
    Optional<Path> report();

    /**
     * Runs BOARD for N ticks, pressing the keys of the script at their ticks, and writes the board after.
     *
     * @param dt empty: the model's default tick
     * @param record where to write the replay of the game
     * @param players how many take turns in the game, 1 to 4
     */
    record Play(Path board, long ticks, Optional<Double> dt, boolean skipBadLines, Optional<Path> out,
                Optional<Path> keys, Optional<Path> report, Optional<Path> record, int players)
            implements HeadlessOptions {
    }

    /** Plays a replay file again and compares the score it reaches with the one it recorded. */
    record Check(Path replay, Optional<Path> report) implements HeadlessOptions {
    }

    /**
     * Plays BOARD {@code games} times with each of the lab's players on {@code threads} threads (every core unless
     * told), each game to game over or {@code gameCapSeconds} of game time, and summarises the games; {@code heatmap}:
     * where to draw where the autoplayer's balls went.
     */
    record Lab(Path board, int games, int threads, double gameCapSeconds, boolean skipBadLines,
               Optional<Path> report, Optional<Path> heatmap) implements HeadlessOptions {
    }

    /** The command line is not one the runner understands; the message says why. */
    final class BadArguments extends Exception {
        private static final long serialVersionUID = 1L;

        BadArguments(String message) {
            super(message);
        }
    }

    static HeadlessOptions parse(List<String> args) throws BadArguments {
        Long ticks = null;
        Optional<Double> dt = Optional.empty();
        boolean skipBadLines = false;
        Optional<Path> out = Optional.empty();
        Optional<Path> keys = Optional.empty();
        Optional<Path> report = Optional.empty();
        Optional<Path> record = Optional.empty();
        Optional<Path> replay = Optional.empty();
        Optional<Path> heatmap = Optional.empty();
        Integer labGames = null;
        Integer players = null;
        Integer threads = null;
        Double gameCap = null;
        Path board = null;
        for (int i = 0; i < args.size(); i++) {
            String arg = args.get(i);
            switch (arg) {
                case "--headless" -> { }
                case "--ticks" -> ticks = OptionValues.ticks(OptionValues.of(args, ++i, arg));
                case "--dt" -> dt = Optional.of(OptionValues.dt(OptionValues.of(args, ++i, arg)));
                case "--skip-bad-lines" -> skipBadLines = true;
                case "--out" -> out = Optional.of(OptionValues.path(OptionValues.of(args, ++i, arg)));
                case "--keys" -> keys = Optional.of(OptionValues.path(OptionValues.of(args, ++i, arg)));
                case "--report" -> report = Optional.of(OptionValues.path(OptionValues.of(args, ++i, arg)));
                case "--record" -> record = Optional.of(OptionValues.path(OptionValues.of(args, ++i, arg)));
                case "--replay" -> replay = Optional.of(OptionValues.path(OptionValues.of(args, ++i, arg)));
                case "--players" -> players = OptionValues.players(OptionValues.of(args, ++i, arg));
                case "--lab" -> labGames = OptionValues.count(OptionValues.of(args, ++i, arg), arg);
                case "--threads" -> threads = OptionValues.count(OptionValues.of(args, ++i, arg), arg);
                case "--heatmap" -> heatmap = Optional.of(OptionValues.path(OptionValues.of(args, ++i, arg)));
                case "--game-cap" -> gameCap = OptionValues.seconds(OptionValues.of(args, ++i, arg), arg);
                default -> {
                    // "-" alone would be a file name; anything else with a dash is an option, never a board.
                    if (arg.startsWith("-") && arg.length() > 1) {
                        throw new BadArguments("unknown option " + arg);
                    }
                    if (board != null) {
                        throw new BadArguments("more than one board file: " + board + " and " + arg);
                    }
                    board = OptionValues.path(arg);
                }
            }
        }
        if (labGames == null && (threads != null || gameCap != null || heatmap.isPresent())) {
            throw new BadArguments((threads != null ? "--threads" : gameCap != null ? "--game-cap" : "--heatmap")
                    + " goes with --lab N");
        }
        if (labGames != null) {
            // The lab plays its own games: no script, no tick count, no single game's outputs.
            if (replay.isPresent() || ticks != null || dt.isPresent() || keys.isPresent() || record.isPresent()
                    || out.isPresent() || players != null) {
                throw new BadArguments("--lab takes only --threads, --game-cap, --skip-bad-lines, --report and --heatmap:"
                        + " its players press the keys and each game runs to game over or the cap");
            }
            if (board == null) {
                throw new BadArguments("no board file given");
            }
            return new Lab(board, labGames, threads != null ? threads : Runtime.getRuntime().availableProcessors(),
                    gameCap != null ? gameCap : LabSettings.DEFAULT_GAME_CAP_SECONDS, skipBadLines,
                    report, heatmap);
        }
        if (replay.isPresent()) {
            // The replay holds the board, the ticks, the tick length and the keys: nothing may say otherwise.
            if (board != null || ticks != null || dt.isPresent() || keys.isPresent() || record.isPresent()
                    || out.isPresent() || skipBadLines || players != null) {
                throw new BadArguments("--replay takes only --report: the replay file holds the board, its ticks,"
                        + " keys and players");
            }
            return new Check(replay.get(), report);
        }
        if (ticks == null) {
            throw new BadArguments("--ticks N is required");
        }
        if (board == null) {
            throw new BadArguments("no board file given");
        }
        return new Play(board, ticks, dt, skipBadLines, out, keys, report, record, players != null ? players : 1);
    }
}
