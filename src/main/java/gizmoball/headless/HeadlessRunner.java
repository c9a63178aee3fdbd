package gizmoball.headless;

import gizmoball.boardfile.AtomicFileWriter;
import gizmoball.boardfile.BoardFileError;
import gizmoball.boardfile.BoardFileException;
import gizmoball.boardfile.BoardFiles;
import gizmoball.boardfile.FileErrors;
import gizmoball.boardfile.LoadResult;
import gizmoball.lab.Lab;
import gizmoball.lab.LabReport;
import gizmoball.lab.LabResult;
import gizmoball.lab.LabSettings;
import gizmoball.model.Board;
import gizmoball.replay.GameReport;
import gizmoball.replay.KeyScript;
import gizmoball.replay.Replay;
import gizmoball.replay.ReplayFiles;
import gizmoball.replay.ScriptedPlay;
import gizmoball.view.HeatMapPicture;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

/**
 * Runs a board without a window, for scripts and tests: loads it, runs N ticks (pressing the keys of a script at their
 * ticks) and writes the resulting board (balls at their new positions and velocities) in canonical form to a file or
 * standard output, with the game's JSON report and its replay file if asked. Or plays a replay file again and says
 * whether it reaches the score it recorded.
 */
public final class HeadlessRunner {
    public static final int OK = 0;
    public static final int BAD_INPUT = 2;
    public static final int WRITE_FAILED = 3;
    /** A replay reached another score than the one it recorded. */
    public static final int REPLAY_DIFFERS = 4;
    /** Pixels across the board of a heat map the lab draws. */
    private static final int HEAT_MAP_SIDE = 640;

    private HeadlessRunner() {
    }

    /** A run that cannot go on: the exit status, the message already printed. */
    private static final class Stop extends Exception {
        private static final long serialVersionUID = 1L;
        private final int status;

        Stop(int status) {
            super(null, null, false, false);
            this.status = status;
        }
    }

    /**
     * Exit status: {@link #OK}, {@link #BAD_INPUT} (bad board, script, replay or arguments), {@link #WRITE_FAILED}
     * or {@link #REPLAY_DIFFERS}.
     */
    public static int run(List<String> args, PrintStream out, PrintStream err) {
        HeadlessOptions options;
        try {
            options = HeadlessOptions.parse(args);
        } catch (HeadlessOptions.BadArguments e) {
            err.println("gizmoball: " + e.getMessage());
            err.println(HeadlessOptions.USAGE);
            return BAD_INPUT;
        }
        try {
            if (options instanceof HeadlessOptions.Play play) {
                return play(play, out, err);
            }
            return options instanceof HeadlessOptions.Lab lab ? lab(lab, out, err)
                    : check((HeadlessOptions.Check) options, out, err);
        } catch (Stop stop) {
            return stop.status;
        }
    }

    private static int play(HeadlessOptions.Play options, PrintStream out, PrintStream err) throws Stop {
        Board board = load(options, err);
        KeyScript keys = options.keys().isPresent() ? keys(options.keys().get(), err) : KeyScript.NONE;
        String asBuilt = BoardFiles.toText(board);
        board.setPlayers(options.players());
        double dt = options.dt().orElse(Board.DEFAULT_TICK);
        ScriptedPlay.play(board, keys, options.ticks(), dt);
        report(board, options.report(), err);
        if (options.record().isPresent()) {
            Path file = options.record().get();
            writeFile(file, () -> ReplayFiles.write(Replay.of(asBuilt, board, dt), file), err);
        }
        return write(board, options, out, err);
    }

    private static int check(HeadlessOptions.Check options, PrintStream out, PrintStream err) throws Stop {
        Path file = options.replay();
        Replay replay;
        try {
            replay = ReplayFiles.read(file);
        } catch (IOException e) {
            err.println("gizmoball: " + FileErrors.cannotRead(file, e));
            throw new Stop(BAD_INPUT);
        } catch (ReplayFiles.BadReplay e) {
            err.println("gizmoball: " + e.getMessage());
            throw new Stop(BAD_INPUT);
        }
        Board board;
        try {
            board = replay.replayed(file + " (its board)");
        } catch (BoardFileException e) {
            err.println("gizmoball: " + file + ": its board does not load, " + e.getMessage());
            throw new Stop(BAD_INPUT);
        }
        report(board, options.report(), err);
        long score = board.game().score();
        out.println("score " + score + " after " + board.ticks() + " ticks");
        if (score != replay.score()) {
            err.println("gizmoball: " + file + ": the replay reaches " + score + ", not the " + replay.score()
                    + " it recorded");
            return REPLAY_DIFFERS;
        }
        return OK;
    }

    private static int lab(HeadlessOptions.Lab options, PrintStream out, PrintStream err) throws Stop {
        Board board = load(options.board(), options.skipBadLines(), err);
        LabSettings settings = LabSettings.of(options.games()).withThreads(options.threads())
                .withGameCap(options.gameCapSeconds());
        LabResult result = Lab.run(board, options.board().toString(), settings, new ProgressLine(err));
        LabReport report = result.report();
        if (options.report().isPresent()) {
            Path file = options.report().get();
            String json = report.toJson();
            writeFile(file, () -> AtomicFileWriter.write(file, w -> w.write(json)), err);
        }
        if (options.heatmap().isPresent()) {
            Path file = options.heatmap().get();
            byte[] png = HeatMapPicture.png(HeatMapPicture.image(board, result.autoplayerHeat(), HEAT_MAP_SIDE,
                    report.heatMapCaption()));
            writeFile(file, () -> Files.write(file, png), err);
        }
        out.println(report.summaryLine());
        return OK;
    }

    private static Board load(HeadlessOptions.Play options, PrintStream err) throws Stop {
        return load(options.board(), options.skipBadLines(), err);
    }

    private static Board load(Path file, boolean skipBadLines, PrintStream err) throws Stop {
        try {
            if (!skipBadLines) {
                return BoardFiles.load(file);
            }
            LoadResult result = BoardFiles.loadSkippingBadLines(file);
            for (BoardFileError skipped : result.skippedLines()) {
                err.println("skipped " + skipped);
            }
            return result.board();
        } catch (IOException e) {
            err.println("gizmoball: " + FileErrors.cannotRead(file, e));
        } catch (BoardFileException e) {
            err.println("gizmoball: " + file + " not loaded, " + e.getMessage());
        }
        throw new Stop(BAD_INPUT);
    }

    private static KeyScript keys(Path file, PrintStream err) throws Stop {
        try {
            return KeyScript.parse(file.toString(), Files.readString(file, StandardCharsets.UTF_8));
        } catch (IOException e) {
            err.println("gizmoball: " + FileErrors.cannotRead(file, e));
        } catch (KeyScript.BadScript e) {
            err.println("gizmoball: " + e.getMessage());
        }
        throw new Stop(BAD_INPUT);
    }

    private static void report(Board board, Optional<Path> report, PrintStream err) throws Stop {
        if (report.isPresent()) {
            String json = GameReport.of(board).toJson();
            writeFile(report.get(), () -> AtomicFileWriter.write(report.get(), w -> w.write(json)), err);
        }
    }

    @FunctionalInterface
    private interface Writing {
        void run() throws IOException;
    }

    private static void writeFile(Path file, Writing writing, PrintStream err) throws Stop {
        try {
            writing.run();
        } catch (IOException e) {
            err.println("gizmoball: " + FileErrors.cannotSave(file, e));
            throw new Stop(WRITE_FAILED);
        }
    }

    private static int write(Board board, HeadlessOptions.Play options, PrintStream out, PrintStream err) {
        if (options.out().isPresent()) {
            try {
                BoardFiles.save(board, options.out().get());
            } catch (IOException e) {
                err.println("gizmoball: " + FileErrors.cannotSave(options.out().get(), e));
                return WRITE_FAILED;
            }
        } else {
            out.print(BoardFiles.toText(board));
            out.flush();
            if (out.checkError()) {
                err.println("gizmoball: cannot write the board to standard output");
                return WRITE_FAILED;
            }
        }
        return OK;
    }
}
