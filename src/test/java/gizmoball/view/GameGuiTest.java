package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.clickMenu;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.tuple;

import gizmoball.controller.Speed;
import gizmoball.highscore.HighScore;
import gizmoball.highscore.HighScoreTable;
import gizmoball.boardfile.BoardFiles;
import java.awt.AWTException;
import java.awt.Dimension;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Toolkit;
import java.awt.Window;
import java.awt.event.KeyEvent;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JTable;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The window as a game: the score panel and the launch hint on the default board, a game played to its end, the
 * game-over dialog taking a name for the board's table, the table, and Watch replaying that entry's game to its
 * score. Each step leaves a screenshot in build/screenshots for a person to look at.
 */
class GameGuiTest extends GameWindowFixture {
    /**
     * No gravity or friction: Space fires the ball from the drain straight up into the square (15.5 L away, 125
     * points) and straight back down into the drain. One ball a game.
     */
    private static final String ONE_SHOT = """
            Square S 19 2
            Absorber A 0 19 20 20
            Ball B 19.75 19.75 0.0 0.0
            KeyConnect key 32 down A
            Gravity 0.0
            Friction 0.0 0.0
            #@Balls 1
            #@Drain A
            #@Points S 125
            """;
    private static final Path SHOTS = Path.of("build", "screenshots");


    /** The screen as the player sees it, window and dialogs, saved for looking at. */
    private static void screenshot(String name) throws IOException, AWTException {
        Gui.sleep(300);
        Files.createDirectories(SHOTS);
        Rectangle screen = new Rectangle(Toolkit.getDefaultToolkit().getScreenSize());
        ImageIO.write(new Robot().createScreenCapture(screen), "png", SHOTS.resolve(name + ".png").toFile());
    }

    private List<String> cells() {
        return onEdt(() -> app.gameFeatures().scorePanel().cells().stream().map(ScorePanel.Cell::text).toList());
    }

    @Test
    void theDefaultBoardShowsScoreBallsAndBestAndSaysWhichKeyLaunches() throws Exception {
        launch(Path.of("boards", "default.txt"));

        assertThat(cells()).containsExactly("Score 0", "Balls 3", "Best -");
        assertThat(onEdt(() -> app.gameFeatures().launchHint().current().map(LaunchHint.Hint::text)))
                .hasValue("Press Space to launch");
        screenshot("game-default-start");

        // Space serves the ball up into the plunger and pulls it while held; the release launches it.
        onEdt(() -> {
            app.session().board().keyDown(KeyEvent.VK_SPACE);
            for (int tick = 0; tick < 30; tick++) {
                app.loop().step();
            }
            app.session().board().keyUp(KeyEvent.VK_SPACE);
            app.loop().step();
        });
        assertThat(onEdt(() -> app.gameFeatures().launchHint().current())).as("the ball is on its way").isEmpty();
        // The narrowest the window goes: the score panel still says everything.
        Dimension smallest = onEdt(() -> app.window().getMinimumSize());
        onEdt(() -> app.window().setSize(smallest));
        await("the narrow window laid out", () -> app.window().getWidth() == smallest.width);
        screenshot("game-default-narrow");
        assertThat(cells()).containsExactly("Score 0", "Balls 3", "Best -");
    }

    /**
     * Issue 40 item 5: at game over nothing stays lit. The drain takes the last ball in the game's last tick, so
     * its flash had just begun when the clock stopped with the game.
     */
    @Test
    void atGameOverNoFlashStaysLit(@TempDir Path dir) throws Exception {
        Path file = Files.writeString(dir.resolve("one-shot.txt"), ONE_SHOT);
        launch(file);
        onEdt(() -> app.session().board().keyDown(KeyEvent.VK_SPACE));
        onEdt(() -> app.session().board().keyUp(KeyEvent.VK_SPACE));
        clickMenu(app.window().menus(), "Start");
        await("the game-over dialog", () -> Gui.showingWindow("gameover.dialog").isPresent());

        gizmoball.model.Board board = app.session().board();
        gizmoball.model.gizmo.Gizmo drain = onEdt(() -> board.gizmo("A").orElseThrow());
        assertThat(onEdt(() -> BoardPainter.flash(board.time() - drain.lastTriggeredAt())))
                .as("the drain's flash when the clock stopped").isPositive();
        assertThat(onEdt(() -> board.gizmos().stream().mapToDouble(g -> BoardPainter.glow(board, g)).max()))
                .hasValue(0);
    }

    @Test
    void aGameEndsWithANameForTheTableAndWatchPlaysItAgain(@TempDir Path dir) throws Exception {
        Path file = Files.writeString(dir.resolve("one-shot.txt"), ONE_SHOT);
        launch(file);
        assertThat(cells()).containsExactly("Score 0", "Balls 1", "Best -");

        onEdt(() -> app.session().board().keyDown(KeyEvent.VK_SPACE));
        onEdt(() -> app.session().board().keyUp(KeyEvent.VK_SPACE));
        clickMenu(app.window().menus(), "Start");
        await("the game-over dialog", () -> Gui.showingWindow("gameover.dialog").isPresent());
        Window dialog = Gui.showingWindow("gameover.dialog").orElseThrow();
        assertThat(onEdt(() -> Gui.find(dialog, JLabel.class, l -> "gameover.score".equals(l.getName()))
                .orElseThrow().getText())).isEqualTo("Final score: 125");
        assertThat(onEdt(() -> Gui.find(dialog, JLabel.class, l -> "gameover.place".equals(l.getName()))
                .orElseThrow().getText())).startsWith("A new best for this board!");
        JTextField name = onEdt(() -> Gui.find(dialog, JTextField.class, f -> "gameover.name".equals(f.getName()))
                .orElseThrow());
        onEdt(() -> name.setText("Ada"));
        screenshot("game-over-dialog");
        onEdt(() -> Gui.find(dialog, JButton.class, b -> "Keep my score".equals(b.getText())).orElseThrow().doClick(0));
        await("the dialog gone", () -> Gui.showingWindow("gameover.dialog").isEmpty());

        assertThat(cells()).containsExactly("Score 125", "Game over", "Best 125 Ada");
        HighScoreTable table = settings.highScores().load(BoardFiles.toText(app.session().boardToSave())).table();
        assertThat(table.entries()).extracting(HighScore::name, HighScore::score)
                .containsExactly(tuple("Ada", 125L));
        assertThat(settings.playerName()).isEqualTo("Ada");
        long gameTicks = table.entries().get(0).replay().ticks();

        SwingUtilities.invokeLater(() -> Gui.menuItem(app.window().menus(), "High scores...").doClick(0));
        await("the table", () -> Gui.showingWindow("highscores.dialog").isPresent());
        Window scores = Gui.showingWindow("highscores.dialog").orElseThrow();
        JTable rows = onEdt(() -> Gui.find(scores, JTable.class, t -> true).orElseThrow());
        assertThat(onEdt(() -> List.of(rows.getValueAt(0, 1), rows.getValueAt(0, 2)))).containsExactly("Ada", "125");
        screenshot("game-high-scores");
        onEdt(() -> app.loop().setSpeed(Speed.QUARTER));
        onEdt(() -> Gui.find(scores, JButton.class, b -> "highscores.watch".equals(b.getName())).orElseThrow()
                .doClick(0));

        await("the replay under way", () -> app.loop().isWatching() && app.session().board().ticks() > 5);
        assertThat(cells()).contains("Watching Ada's 125");
        assertThat(onEdt(() -> app.gameFeatures().launchHint().current())).as("no hint while watching").isEmpty();
        screenshot("game-watching");
        await("the replay's end", () -> !app.loop().isWatching() && !app.loop().isRunning());
        assertThat(onEdt(() -> app.session().board().ticks())).isEqualTo(gameTicks);
        assertThat(cells()).containsExactly("Score 125", "Game over", "Best 125 Ada", "Replay over");
        assertThat(onEdt(() -> app.window().statusLine().text())).contains("Replay over: 125 points, as recorded");
        assertThat(Gui.showingWindow("gameover.dialog")).as("a watched game over asks nothing").isEmpty();
        screenshot("game-replay-over");

        clickMenu(app.window().menus(), "New game");
        await("a new game", () -> app.session().board().ticks() > 0 || app.loop().isRunning());
        assertThat(cells()).containsExactly("Score 0", "Balls 1", "Best 125 Ada");
        onEdt(() -> app.loop().stop());
        assertThat(onEdt(() -> app.session().board().balls().size())).isEqualTo(1);
    }
}
