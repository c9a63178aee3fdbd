package gizmoball.controller;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardContents;
import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.replay.Replay;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * A game played through the window's game loop, its clock injected (real time arriving in uneven steps, late events
 * catching up by several ticks or dropping time), with keys pressed between timer events as the player presses them,
 * replays headless to the same game bit for bit: at every speed, frame timing changes nothing a replay depends on.
 */
class GameLoopReplayTest {
    private static final long TICKS = 1_500;

    /** Key bindings whose actions wait: delays run on the board's clock, so they replay as the keys do. */
    private static final String DELAYED_BINDINGS = """
            #@KeyConnect key 88 down Plunger after 0.75
            #@KeyConnect key 67 down LF toggle after 0.2
            #@KeyConnect key 67 up RF raise after 0.05
            """;

    @ParameterizedTest
    @EnumSource(Speed.class)
    void aGameOfTheWindowsLoopReplaysHeadlessBitForBit(Speed speed) throws Exception {
        playAndReplay(BoardFiles.load(Path.of("boards", "default.txt")), speed);
    }

    @ParameterizedTest
    @EnumSource(Speed.class)
    void aGameWithDelayedActionsReplaysHeadlessBitForBitAtEverySpeed(Speed speed) throws Exception {
        String text = BoardFiles.toText(BoardFiles.load(Path.of("boards", "default.txt"))) + DELAYED_BINDINGS;
        playAndReplay(BoardFiles.load("delayed", text), speed);
    }

    private static void playAndReplay(Board board, Speed speed) throws Exception {
        String asBuilt = BoardFiles.toText(board);
        List<Integer> keys = board.keyBindings().stream().map(KeyBinding::keyCode).distinct().toList();
        GameLoop loop = new GameLoop(board, Board.DEFAULT_TICK);
        loop.setSpeed(speed);
        Random random = new Random(speed.ordinal());

        while (board.ticks() < TICKS) {
            // 0 to 100 ms of real time: from no tick at all to the most catch-up, and time dropped beyond it.
            loop.elapsed(random.nextInt(100_000_000));
            if (random.nextInt(3) == 0) {
                int key = keys.get(random.nextInt(keys.size()));
                if (random.nextBoolean()) {
                    board.keyDown(key);
                } else {
                    board.keyUp(key);
                }
            }
        }

        Board again = Replay.of(asBuilt, board, Board.DEFAULT_TICK).replayed("default.txt");
        assertThat(again.ticks()).isEqualTo(board.ticks());
        assertThat(again.game().score()).isEqualTo(board.game().score());
        assertThat(again.game().scoringHits()).isEqualTo(board.game().scoringHits());
        assertThat(again.game().drains()).isEqualTo(board.game().drains());
        assertThat(BoardContents.of(again).balls()).isEqualTo(BoardContents.of(board).balls());
    }
}
