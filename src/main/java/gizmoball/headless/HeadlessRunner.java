package gizmoball.headless;

import gizmoball.boardfile.BoardFileError;
import gizmoball.boardfile.BoardFileException;
import gizmoball.boardfile.BoardFiles;
import gizmoball.boardfile.FileErrors;
import gizmoball.boardfile.LoadResult;
import gizmoball.model.Board;
import java.io.IOException;
import java.io.PrintStream;
import java.util.List;

/**
 * Runs a board without a window, for scripts and tests: loads it, runs N ticks and writes the resulting board
 * (balls at their new positions and velocities) in canonical form to a file or standard output.
 */
public final class HeadlessRunner {
    public static final int OK = 0;
    public static final int BAD_INPUT = 2;
    public static final int WRITE_FAILED = 3;

    private HeadlessRunner() {
    }

    /** Exit status: {@link #OK}, {@link #BAD_INPUT} (bad board or arguments) or {@link #WRITE_FAILED}. */
    public static int run(List<String> args, PrintStream out, PrintStream err) {
        HeadlessOptions options;
        try {
            options = HeadlessOptions.parse(args);
        } catch (HeadlessOptions.BadArguments e) {
            err.println("gizmoball: " + e.getMessage());
            err.println(HeadlessOptions.USAGE);
            return BAD_INPUT;
        }
        Board board;
        try {
            board = load(options, err);
        } catch (IOException e) {
            err.println("gizmoball: " + FileErrors.cannotRead(options.board(), e));
            return BAD_INPUT;
        } catch (BoardFileException e) {
            err.println("gizmoball: " + options.board() + " not loaded, " + e.getMessage());
            return BAD_INPUT;
        }
        double dt = options.dt().orElse(Board.DEFAULT_TICK);
        for (long tick = 0; tick < options.ticks(); tick++) {
            board.tick(dt);
        }
        return write(board, options, out, err);
    }

    private static Board load(HeadlessOptions options, PrintStream err) throws IOException, BoardFileException {
        if (!options.skipBadLines()) {
            return BoardFiles.load(options.board());
        }
        LoadResult result = BoardFiles.loadSkippingBadLines(options.board());
        for (BoardFileError skipped : result.skippedLines()) {
            err.println("skipped " + skipped);
        }
        return result.board();
    }

    private static int write(Board board, HeadlessOptions options, PrintStream out, PrintStream err) {
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
