package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.clickMenu;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.tuple;

import gizmoball.boardfile.BoardFiles;
import gizmoball.controller.Speed;
import gizmoball.highscore.HighScore;
import gizmoball.highscore.HighScoreTable;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Toolkit;
import java.awt.Window;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JTextField;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Two players in the window, played to game over: the score strip shows both scores and whose turn it is, the game
 * over asks each player's name in turn, both enter the table, and watching a player's entry replays the two-player
 * game to its score. Screenshots in build/screenshots.
 */
class TwoPlayerGuiTest extends GameWindowFixture {
    /**
     * No gravity or friction: Space fires the ball from the drain straight up into the square (125 points) and it comes
     * straight back; Up nudges it 4 L/s faster on its way.
     */
    private static final String ONE_SHOT = """
            Square S 19 2
            Absorber A 0 19 20 20
            Ball B 19.75 19.75 0.0 0.0
            KeyConnect key 32 down A
            Gravity 0.0
            Friction 0.0 0.0
            #@Balls 1
            #@Nudge 4.0 37 39 38
            #@Drain A
            #@Points S 125
            """;
    private static final Path SHOTS = Path.of("build", "screenshots");


    private static void screenshot(String name) throws Exception {
        Gui.sleep(300);
        Files.createDirectories(SHOTS);
        Rectangle screen = new Rectangle(Toolkit.getDefaultToolkit().getScreenSize());
        ImageIO.write(new Robot().createScreenCapture(screen), "png", SHOTS.resolve(name + ".png").toFile());
    }

    private List<String> cells() {
        return onEdt(() -> app.gameFeatures().scorePanel().cells().stream().map(ScorePanel.Cell::text).toList());
    }

    private void answer(String who, String score, String name) throws Exception {
        await(who + "'s game-over dialog", () -> Gui.showingWindow("gameover.dialog")
                .map(d -> onEdt(() -> Gui.find(d, JLabel.class, l -> "gameover.score".equals(l.getName()))
                        .orElseThrow().getText()).startsWith(who)).orElse(false));
        Window dialog = Gui.showingWindow("gameover.dialog").orElseThrow();
        assertThat(onEdt(() -> Gui.find(dialog, JLabel.class, l -> "gameover.score".equals(l.getName()))
                .orElseThrow().getText())).isEqualTo(who + ", final score: " + score);
        JTextField field = onEdt(() -> Gui.find(dialog, JTextField.class, f -> "gameover.name".equals(f.getName()))
                .orElseThrow());
        onEdt(() -> field.setText(name));
        screenshot("players-over-" + name);
        onEdt(() -> Gui.find(dialog, JButton.class, b -> "Keep my score".equals(b.getText())).orElseThrow()
                .doClick(0));
    }

    @Test
    void twoPlayersTakeTurnsToGameOverAndEachNameEntersTheTable(@TempDir Path dir) throws Exception {
        launch(dir.resolve("one-shot.txt"), ONE_SHOT);
        clickMenu(app.window().menus(), "2 players");
        onEdt(() -> app.loop().setSpeed(Speed.HALF));
        assertThat(cells()).containsExactly("> P1 0", "P2 0", "Balls 1", "Best -");

        onEdt(() -> app.session().board().keyDown(KeyEvent.VK_SPACE));
        onEdt(() -> app.session().board().keyUp(KeyEvent.VK_SPACE));
        await("player 2's turn", () -> onEdt(() -> app.session().board().game().currentPlayer()) == 1);
        assertThat(cells()).containsExactly("P1 125", "> P2 0", "Balls 1", "Best -");
        screenshot("players-turn-2");

        onEdt(() -> app.session().board().keyDown(KeyEvent.VK_SPACE));
        onEdt(() -> app.session().board().keyUp(KeyEvent.VK_SPACE));
        onEdt(() -> {   // the ball is on its way up: a nudge up speeds it to the square
            app.session().board().keyDown(KeyEvent.VK_UP);
            app.session().board().keyUp(KeyEvent.VK_UP);
        });
        answer("Player 1", "125", "Ada");
        answer("Player 2", "125", "Bob");
        await("the dialogs gone", () -> Gui.showingWindow("gameover.dialog").isEmpty());
        assertThat(cells()).containsExactly("P1 125", "P2 125", "Game over", "Best 125 Ada");
        screenshot("players-game-over");

        HighScoreTable table = settings.highScores().load(BoardFiles.toText(app.session().boardToSave())).table();
        assertThat(table.entries()).extracting(HighScore::name, HighScore::score)
                .containsExactly(tuple("Ada", 125L), tuple("Bob", 125L));
        assertThat(table.entries().get(0).replay().players()).isEqualTo(2);

        onEdt(() -> app.loop().setSpeed(Speed.DOUBLE));
        onEdt(() -> app.gameFeatures().commands().watch(table.entries().get(0).replay(), "the game of Ada's 125"));
        await("the replay's end", () -> !app.loop().isWatching() && !app.loop().isRunning());
        assertThat(cells()).containsExactly("P1 125", "P2 125", "Game over", "Best 125 Ada", "Replay over");
        assertThat(onEdt(() -> app.window().statusLine().text())).contains("Replay over: 250 points, as recorded");
        screenshot("players-replay-over");
    }
}
