package gizmoball.replay;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardFileException;
import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.game.Drain;
import gizmoball.model.game.KeyPress;
import gizmoball.model.game.Notice;
import gizmoball.model.loop.BallView;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every shipped board that is a game can be played to its end: its drain's key launches each ball (through the plunger
 * where the table has one, held for a full pull), and a player who only launches (never touches a flipper) loses every
 * ball, one drain each (and one for each ball a multiball adds), and the game ends with a score.
 */
class ShippedGamesTest {
    private static final long GIVE_UP = 120 * 60;
    /** Ticks the launch key is held: a full pull of every shipped plunger. */
    private static final long HOLD = 100;

    static Stream<Path> games() throws IOException, BoardFileException {
        List<Path> games = new ArrayList<>();
        try (Stream<Path> files = Files.list(Path.of("boards"))) {
            for (Path file : files.filter(f -> f.toString().endsWith(".txt")).sorted().toList()) {
                if (BoardFiles.load(file).gameRules().isGame()) {
                    games.add(file);
                }
            }
        }
        assertThat(games).extracting(p -> p.getFileName().toString()).contains("default.txt", "arcade.txt", "orbit.txt",
                "castle.txt");
        return games.stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("games")
    void launchingEachBallAndNothingElsePlaysTheGameToItsEnd(Path file) throws Exception {
        Board board = BoardFiles.load(file);
        List<Integer> launchKeys = board.keyBindings().stream()
                .filter(k -> board.gameRules().isDrain(k.gizmo()) && k.edge() != KeyEdge.UP)
                .map(KeyBinding::keyCode).distinct().toList();
        assertThat(launchKeys).as("a key launches from the drain").isNotEmpty();
        int balls = board.game().ballsLeft();

        // Every two seconds, the launch key down and, a full pull later, up again.
        List<KeyPress> keys = new ArrayList<>();
        for (long tick = 0; tick < GIVE_UP; tick += 120) {
            keys.add(new KeyPress(tick, KeyPress.Motion.DOWN, launchKeys.get(0)));
            keys.add(new KeyPress(tick + HOLD, KeyPress.Motion.UP, launchKeys.get(0)));
        }
        ScriptedPlay play = new ScriptedPlay(board, new KeyScript(keys), Board.DEFAULT_TICK);
        while (!board.game().isOver() && board.ticks() < GIVE_UP) {
            play.tick();
        }

        assertThat(board.game().isOver()).as("over within two minutes of play").isTrue();
        // One drain for each ball of the game, the extra ball if it was won, each ball a multiball added, and each
        // ball the ball save gave back.
        Set<String> first = BoardFiles.load(file).balls().stream().map(BallView::name).collect(Collectors.toSet());
        long added = board.game().drains().stream().map(Drain::ball).filter(b -> !first.contains(b)).distinct().count();
        int extra = board.game().extraBallTick().isPresent() ? 1 : 0;
        long saved = board.game().notices().stream().filter(n -> n.kind() == Notice.Kind.BALL_SAVED).count();
        assertThat(board.game().drains()).hasSize(balls + extra + (int) added + (int) saved);
        assertThat(board.game().score()).isPositive();
    }
}
