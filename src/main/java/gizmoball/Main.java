package gizmoball;

import gizmoball.app.Gizmoball;
import gizmoball.headless.HeadlessOptions;
import gizmoball.headless.HeadlessRunner;
import gizmoball.view.WindowClass;
import java.awt.AWTError;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;
import javax.swing.SwingUtilities;

/**
 * Entry point: the command line of both modes. {@code gizmoball [BOARD]} plays a board in a window (default:
 * boards/default.txt of the installation or the working directory, else the sample inside the game);
 * {@code gizmoball --headless ...} runs one without a window (see {@link HeadlessRunner}). Every refusal is
 * one line on standard error and an exit status, never a stack trace.
 */
public final class Main {
    public static final int OK = 0;
    /** Bad arguments, a bad board, or no display for the window (also {@link HeadlessRunner#BAD_INPUT}). */
    public static final int BAD_USAGE = 2;

    public static final String USAGE = String.join(System.lineSeparator(),
            "usage: gizmoball [BOARD]        play BOARD in a window (default: boards/default.txt)",
            "       " + HeadlessOptions.PLAY_USAGE,
            "                                run BOARD for N ticks without a window (pressing the keys of SCRIPT),",
            "                                print the board after; --report: the game as JSON, --record: its replay",
            "       " + HeadlessOptions.CHECK_USAGE,
            "                                play a replay again, print its score; exit 4 if it is not the recorded one",
            "       " + HeadlessOptions.LAB_USAGE,
            "                                play BOARD N times with an autoplayer and N with an idle player (launches",
            "                                only) on N threads (default: every core), each game to game over or the",
            "                                cap (default 600 s of game time); print whether the flippers matter;",
            "                                --report: scores, seconds per ball, drains, hits, jams as JSON;",
            "                                --heatmap: a PNG of where the autoplayer's balls went over the board",
            "       gizmoball --help | -h    show this help",
            "       gizmoball --version      show the version",
            "exit status: 0 done, 2 bad arguments, bad board or no display, 3 output not written (--headless),",
            "             4 the replay reached another score");
    static final String NO_DISPLAY = "gizmoball: no display: set DISPLAY or use --headless";

    /** Set by the installed start script to the installation directory, which ships boards/. */
    private static final String HOME_PROPERTY = "gizmoball.home";
    private static final Path DEFAULT_BOARD = Path.of("boards", "default.txt");
    private static final String DEFAULT_SAMPLE = "default.txt";

    private Main() {
    }

    public static void main(String[] args) {
        OptionalInt status = run(List.of(args), System.out, System.err, !GraphicsEnvironment.isHeadless());
        if (status.isPresent()) {
            System.exit(status.getAsInt());
        }
    }

    /**
     * Does what the command line says. Returns the exit status, or nothing when a window opened (the program
     * then lives until the window closes).
     */
    static OptionalInt run(List<String> args, PrintStream out, PrintStream err, boolean display) {
        if (args.contains("--help") || args.contains("-h")) {
            out.println(USAGE);
            return OptionalInt.of(OK);
        }
        if (args.contains("--version")) {
            out.println("gizmoball " + Version.current());
            return OptionalInt.of(OK);
        }
        if (args.contains("--headless")) {
            return OptionalInt.of(HeadlessRunner.run(args, out, err));
        }
        Optional<Path> board;
        try {
            board = boardOf(args);
        } catch (IllegalArgumentException e) {
            err.println("gizmoball: " + e.getMessage());
            err.println(USAGE);
            return OptionalInt.of(BAD_USAGE);
        }
        if (!display) {
            err.println(NO_DISPLAY);
            return OptionalInt.of(BAD_USAGE);
        }
        try {
            openWindow(board);
        } catch (RuntimeException | AWTError e) {
            Optional<String> why = displayProblem(e);
            if (why.isEmpty()) {
                throw e;
            }
            err.println(why.get());
            return OptionalInt.of(BAD_USAGE);
        }
        return OptionalInt.empty();
    }

    /** The board named on a window-mode command line, or the default one; refuses options and extra names. */
    private static Optional<Path> boardOf(List<String> args) {
        List<String> names = new ArrayList<>();
        boolean options = true;
        for (String arg : args) {
            if (options && arg.equals("--")) {
                options = false;
            } else if (options && arg.startsWith("-") && arg.length() > 1) {
                throw new IllegalArgumentException("unknown option " + arg);
            } else {
                names.add(arg);
            }
        }
        if (names.size() > 1) {
            throw new IllegalArgumentException("more than one board file: " + String.join(", ", names));
        }
        try {
            return names.isEmpty() ? defaultBoard() : Optional.of(Path.of(names.get(0)));
        } catch (InvalidPathException e) {
            throw new IllegalArgumentException("not a file name: " + names.get(0));
        }
    }

    private static void openWindow(Optional<Path> board) {
        WindowClass.name("Gizmoball");
        Gizmoball app = Gizmoball.launch(board.orElse(null));
        if (board.isEmpty()) {
            SwingUtilities.invokeLater(() -> app.files().openSample(DEFAULT_SAMPLE));
        }
    }

    /** One line for a window that could not open for want of a display; empty for any other failure. */
    private static Optional<String> displayProblem(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t instanceof HeadlessException) {
                return Optional.of(NO_DISPLAY);
            }
            if (t instanceof AWTError) {
                return Optional.of("gizmoball: cannot open the display " + System.getenv("DISPLAY") + ": "
                        + t.getMessage());
            }
        }
        return Optional.empty();
    }

    /**
     * boards/default.txt of the installation if there is one, else of the working directory; empty when
     * neither is there (the window then opens the sample inside the game).
     */
    private static Optional<Path> defaultBoard() {
        String home = System.getProperty(HOME_PROPERTY);
        if (home != null) {
            Path installed = Path.of(home).resolve(DEFAULT_BOARD);
            if (Files.isRegularFile(installed)) {
                return Optional.of(installed);
            }
        }
        return Files.isRegularFile(DEFAULT_BOARD) ? Optional.of(DEFAULT_BOARD) : Optional.empty();
    }
}
