package gizmoball;

import gizmoball.app.Gizmoball;
import gizmoball.headless.HeadlessRunner;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Entry point. {@code gizmoball [BOARD]} plays a board (default: boards/default.txt);
 * {@code gizmoball --headless --ticks N [--dt SECONDS] [--skip-bad-lines] [--out FILE] BOARD} runs one without
 * a window (see {@link HeadlessRunner}).
 */
public final class Main {
    /** Set by the installed start script to the installation directory, which ships boards/. */
    private static final String HOME_PROPERTY = "gizmoball.home";
    private static final Path DEFAULT_BOARD = Path.of("boards", "default.txt");

    private Main() {
    }

    public static void main(String[] args) {
        List<String> arguments = List.of(args);
        if (arguments.contains("--headless")) {
            System.exit(HeadlessRunner.run(arguments, System.out, System.err));
        }
        Path board = arguments.isEmpty() ? defaultBoard() : Path.of(arguments.get(0));
        Gizmoball.launch(board);
    }

    /** boards/default.txt of the installation if there is one, else of the working directory. */
    private static Path defaultBoard() {
        String home = System.getProperty(HOME_PROPERTY);
        if (home != null) {
            Path installed = Path.of(home).resolve(DEFAULT_BOARD);
            if (Files.isRegularFile(installed)) {
                return installed;
            }
        }
        return DEFAULT_BOARD;
    }
}
