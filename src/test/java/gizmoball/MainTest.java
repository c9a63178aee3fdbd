package gizmoball;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.app.Gizmoball;
import gizmoball.view.GameWindow;
import gizmoball.view.Gui;
import gizmoball.view.WindowClass;
import java.awt.Frame;
import java.awt.GraphicsEnvironment;
import java.awt.Window;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.OptionalInt;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The command line, in this JVM: every case that needs no window runs with or without a display; the cases
 * that open one need a display (the jar's tests run the same in a JVM that has none, see JarTest).
 */
class MainTest {
    @TempDir
    Path dir;

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private OptionalInt run(boolean display, String... args) {
        return Main.run(List.of(args), new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8), display);
    }

    private String stdout() {
        return out.toString(StandardCharsets.UTF_8);
    }

    private String stderr() {
        return err.toString(StandardCharsets.UTF_8);
    }

    @AfterEach
    void closeWindows() {
        if (!GraphicsEnvironment.isHeadless()) {
            for (Window w : Window.getWindows()) {
                onEdt(w::dispose);
            }
        }
    }

    @Test
    void helpPrintsTheUsageOfBothModesAndExitsZero() {
        for (String help : List.of("--help", "-h")) {
            out.reset();
            assertThat(run(false, help)).hasValue(0);
            assertThat(stdout()).contains("gizmoball [BOARD]", "gizmoball --headless --ticks N", "--version",
                    "exit status");
        }
        assertThat(stderr()).isEmpty();
    }

    @Test
    void versionPrintsTheVersionTheBuildWrote() throws Exception {
        assertThat(run(false, "--version")).hasValue(0);
        String built = Files.readString(Path.of("build.gradle")).lines()
                .filter(l -> l.startsWith("version = ")).findFirst().orElseThrow()
                .replaceAll("version = '(.*)'", "$1");
        assertThat(stdout()).isEqualTo("gizmoball " + built + System.lineSeparator());
    }

    @Test
    void anUnknownOptionIsRefusedWithTheUsageAndExitTwoAndNeverOpenedAsABoard() {
        assertThat(run(true, "--bogus")).hasValue(Main.BAD_USAGE);
        assertThat(stderr()).startsWith("gizmoball: unknown option --bogus").contains(Main.USAGE);
        assertThat(stdout()).isEmpty();
        assertThat(showingFrames()).as("no window opened").isEmpty();
    }

    @Test
    void twoBoardsAreRefused() {
        assertThat(run(true, "a.txt", "b.txt")).hasValue(Main.BAD_USAGE);
        assertThat(stderr()).startsWith("gizmoball: more than one board file: a.txt, b.txt");
    }

    @Test
    void withoutADisplayTheWindowModeSaysSoInOneLineAndExitsTwo() {
        assertThat(run(false)).hasValue(Main.BAD_USAGE);
        assertThat(stderr()).isEqualTo("gizmoball: no display: set DISPLAY or use --headless"
                + System.lineSeparator());
        assertThat(run(false, "boards/default.txt")).hasValue(Main.BAD_USAGE);
    }

    @Test
    void headlessRunsWithoutADisplay() throws Exception {
        Path board = Files.writeString(dir.resolve("b.txt"), "Square S 1 1\n");
        assertThat(run(false, "--headless", "--ticks", "1", board.toString())).hasValue(0);
        assertThat(stdout()).startsWith("Square S 1 1\n");
    }

    @Test
    void withADisplayTheWindowOpensOnTheBoardNamedAsGizmoball() throws Exception {
        Gui.assumeDisplay();
        Path board = Files.writeString(dir.resolve("b.txt"), "Square S 1 1\n");

        assertThat(run(true, board.toString())).as("the program lives on in its window").isEmpty();

        await("the window", () -> showingFrames().stream().anyMatch(f -> f.getTitle().equals("Gizmoball - b.txt")));
        assertThat(WindowClass.current()).as("X11 window class").contains("Gizmoball");
        GameWindow window = (GameWindow) showingFrames().get(0);
        assertThat(onEdt(() -> window.getIconImages())).isNotEmpty();
        assertThat(stderr()).isEmpty();
    }

    @Test
    void withADisplayAndNoBoardsFolderNearTheSampleInsideTheGameOpens() {
        Gui.assumeDisplay();
        // The tests run in the project folder, which has boards/: the sample is what File > Sample boards opens.
        Gizmoball app = Gizmoball.launch(null);
        JMenu samples = (JMenu) Gui.menuItem(app.window().menus(), "Sample boards");
        assertThat(onEdt(samples::isEnabled)).isTrue();
        onEdt(() -> Gui.find(samples.getPopupMenu(), JMenuItem.class, i -> "multiball.txt".equals(i.getText()))
                .orElseThrow().doClick(0));
        assertThat(onEdt(() -> app.session().board().balls())).hasSize(5);
        assertThat(onEdt(() -> app.session().file())).isEmpty();
        assertThat(onEdt(() -> app.window().statusLine().message())).contains("sample board multiball.txt");
    }

    private static List<Frame> showingFrames() {
        return onEdt(() -> Arrays.stream(Frame.getFrames()).filter(Frame::isShowing).toList());
    }
}
