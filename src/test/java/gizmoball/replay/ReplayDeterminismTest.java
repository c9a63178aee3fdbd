package gizmoball.replay;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardContents;
import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * 50 random games on the shipped boards, 3,000 ticks each: the game's own record of its keys, written to a replay file
 * and read back, plays from the board as built to the same score, hits, drains and balls, bit for bit.
 */
class ReplayDeterminismTest {
    private static final int GAMES = 50;
    private static final long TICKS = 3_000;
    private static final double DT = Board.DEFAULT_TICK;

    static Stream<Arguments> games() throws IOException {
        List<Path> boards;
        try (Stream<Path> files = Files.list(Path.of("boards"))) {
            boards = files.filter(f -> f.toString().endsWith(".txt")).sorted().toList();
        }
        return IntStream.range(0, GAMES).mapToObj(seed -> Arguments.of(boards.get(seed % boards.size()), seed));
    }

    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("games")
    void aRecordedGameReplaysBitForBit(Path file, long seed) throws Exception {
        Board board = BoardFiles.load(file);
        String asBuilt = BoardFiles.toText(board);
        ScriptedPlay.play(board, RandomGames.script(board, new Random(seed), TICKS), TICKS, DT);

        Replay replay = ReplayFiles.fromJson("replay", ReplayFiles.toJson(Replay.of(asBuilt, board, DT)));
        Board again = replay.replayed(file.toString());

        assertThat(again.ticks()).isEqualTo(TICKS);
        assertThat(again.game().score()).isEqualTo(board.game().score()).isEqualTo(replay.score());
        assertThat(again.game().scoringHits()).isEqualTo(board.game().scoringHits());
        assertThat(again.game().drains()).isEqualTo(board.game().drains());
        assertThat(again.game().keys()).isEqualTo(board.game().keys());
        // Doubles compared exactly: BoardContents' records compare with Double.compare.
        assertThat(BoardContents.of(again).balls()).isEqualTo(BoardContents.of(board).balls());
    }
}
