package gizmoball.view.editor;

import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.fail;

import gizmoball.session.Mode;
import gizmoball.view.GameWindowFixture;
import gizmoball.view.Gui;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Window;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.function.BooleanSupplier;
import javax.imageio.ImageIO;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JMenuItem;
import javax.swing.JProgressBar;
import javax.swing.JTextArea;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Build mode's Test > Play-test in the window: the lab runs in the background with a progress bar while the window
 * answers, Cancel stops its games, and a finished run shows the heat map and the figures (a screenshot in
 * build/screenshots to look at).
 */
class PlayTestGuiTest extends GameWindowFixture {
    /** A sandbox (no drain): every game plays to the cap, so the lab is still busy when it is cancelled. */
    private static final String SANDBOX = """
            Circle C 10 10
            Ball B 5 5 3 0
            """;
    /**
     * A small table: its games end in seconds. The square Hidden in the top-left corner is walled in by two others, so
     * no ball can touch it.
     */
    private static final String TABLE = """
            Absorber A 0 19 20 20
            Triangle Corner 19 0
            Rotate Corner
            LeftFlipper LF 6 16
            RightFlipper RF 10 16
            Circle C1 4 6
            Circle C2 12 5
            Square Hidden 0 0
            Square Cover1 1 0
            Square Cover2 0 1
            Ball B 19.75 19.75 0 0
            KeyConnect key 90 down LF
            KeyConnect key 90 up LF
            KeyConnect key 47 down RF
            KeyConnect key 47 up RF
            KeyConnect key 32 down A
            #@Balls 2
            #@Drain A
            """;
    private static final Path SHOTS = Path.of("build", "screenshots");
    private static final long LAB_PATIENCE_MILLIS = 120_000;


    private JDialog startPlayTest(Path dir, String board) throws Exception {
        launch(dir.resolve("board.txt"), board);
        JMenuItem item = onEdt(() -> Gui.menuItem(app.window().menus(), "Play-test\u2026"));
        assertThat(onEdt(() -> app.build().testMenu().isEnabled())).as("the Test menu in play mode").isFalse();
        onEdt(() -> app.session().setMode(Mode.BUILD));
        assertThat(onEdt(() -> app.build().testMenu().isEnabled())).as("the Test menu in build mode").isTrue();
        onEdt(() -> item.doClick(0));
        Gui.await("the Play-test window", () -> Gui.showingWindow("playtest").isPresent());
        return (JDialog) Gui.showingWindow("playtest").orElseThrow();
    }

    private static <C extends java.awt.Component> C part(Window dialog, Class<C> type, String name) {
        return onEdt(() -> Gui.find(dialog, type, c -> name.equals(c.getName())).orElseThrow(
                () -> new AssertionError("no " + name)));
    }

    private static boolean labThreadsAlive() {
        return Thread.getAllStackTraces().keySet().stream().anyMatch(t -> t.getName().equals("lab") && t.isAlive());
    }

    private static void awaitLong(String what, BooleanSupplier condition) {
        long deadline = System.currentTimeMillis() + LAB_PATIENCE_MILLIS;
        while (!onEdt(condition::getAsBoolean)) {
            if (System.currentTimeMillis() > deadline) {
                fail("waited in vain for: " + what);
            }
            Gui.sleep(20);
        }
    }

    @Test
    void showsProgressWhileTheWindowAnswersAndCancelStopsTheGames(@TempDir Path dir) throws Exception {
        JDialog dialog = startPlayTest(dir, SANDBOX);
        JProgressBar progress = part(dialog, JProgressBar.class, "playtest.progress");
        awaitLong("a game played", () -> progress.getValue() > 0);
        // The event thread is free while the lab plays: the window's own work gets done meanwhile.
        assertThat(onEdt(() -> progress.getValue() < progress.getMaximum())).isTrue();
        assertThat(labThreadsAlive()).as("the lab's threads, playing").isTrue();
        Files.createDirectories(SHOTS);
        Gui.sleep(200);
        screenshot("play-test-running.png");

        // Asked again while it plays, Play-test brings the running one forward and starts no second lab.
        JMenuItem again = onEdt(() -> Gui.menuItem(app.window().menus(), "Play-test\u2026"));
        onEdt(() -> again.doClick(0));
        Gui.sleep(300);
        assertThat(onEdt(() -> Arrays.stream(Window.getWindows())
                .filter(w -> w.isShowing() && "playtest".equals(w.getName())).toList())).containsExactly(dialog);

        JButton cancel = part(dialog, JButton.class, "playtest.cancel");
        long pressed = System.nanoTime();
        onEdt(() -> cancel.doClick(0));
        Gui.await("the lab's threads to end", () -> !labThreadsAlive());
        System.out.printf("play-test cancelled: its threads ended %.0f ms after Cancel%n",
                (System.nanoTime() - pressed) / 1e6);
        JLabel status = part(dialog, JLabel.class, "playtest.status");
        assertThat(onEdt(() -> status.getText())).startsWith("Cancelled after ");
        assertThat(onEdt(() -> cancel.getText())).isEqualTo("Close");
        onEdt(() -> cancel.doClick(0));
        Gui.await("the Play-test window to close", () -> Gui.showingWindow("playtest").isEmpty());
    }

    @Test
    void aFinishedRunShowsTheHeatMapAndTheGizmosNeverHit(@TempDir Path dir) throws Exception {
        JDialog dialog = startPlayTest(dir, TABLE);
        awaitLong("the play-test to finish", () -> Gui.find(dialog, JLabel.class,
                l -> "playtest.heatmap".equals(l.getName())).isPresent());
        JLabel map = part(dialog, JLabel.class, "playtest.heatmap");
        assertThat(onEdt(() -> map.getIcon().getIconWidth())).isEqualTo(PlayTestDialog.HEAT_MAP_SIDE);
        String figures = onEdt(() -> part(dialog, JTextArea.class, "playtest.figures").getText());
        assertThat(figures).contains("100 games each", "Mean score: autoplayer ", "A ball lasts: autoplayer ",
                "Never hit by the autoplayer: ").containsPattern("Never hit by the autoplayer: [^\\n]*Hidden");
        assertThat(onEdt(() -> part(dialog, JLabel.class, "playtest.status").getText())).contains("autoplayer mean score");
        Gui.sleep(300);
        screenshot("play-test.png");
    }

    private static void screenshot(String name) throws Exception {
        Files.createDirectories(SHOTS);
        Window dialog = Gui.showingWindow("playtest").orElseThrow();
        Rectangle bounds = onEdt(() -> dialog.getBounds());
        ImageIO.write(new Robot().createScreenCapture(bounds), "png", SHOTS.resolve(name).toFile());
    }
}
