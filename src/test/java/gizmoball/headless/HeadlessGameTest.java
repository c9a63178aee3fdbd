package gizmoball.headless;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import gizmoball.model.Board;
import gizmoball.replay.Replay;
import gizmoball.replay.ReplayFiles;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Headless games: a key script played on a board, its JSON report, its replay file, and the replay checked again
 * (docs/running.md, "Headless runner").
 */
class HeadlessGameTest {
    /**
     * No gravity or friction: Space fires the ball from the drain straight up at the launch speed into the square,
     * 15.5 L away, and it comes straight back into the drain. Two balls, 125 points a hit on the square.
     */
    private static final String BOARD = """
            Square S 19 2
            Absorber A 0 19 20 20
            Ball B 19.75 19.75 0.0 0.0
            KeyConnect key 32 down A
            Gravity 0.0
            Friction 0.0 0.0
            #@Balls 2
            #@Drain A
            #@Points S 125
            """;
    /** Space at ticks 0 and 100 (by name and by code): each acts in the next tick. */
    private static final String SCRIPT = """
            # launch, and launch the second ball
            0 down Space
            1 up Space
            100 down 32
            101 up 32
            """;
    private static final double FLIGHT = 15.5 / Board.ABSORBER_LAUNCH_SPEED;

    @TempDir
    Path directory;

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int run(String... args) {
        return HeadlessRunner.run(List.of(args), new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    private Path file(String name, String text) throws IOException {
        return Files.writeString(directory.resolve(name), text);
    }

    /** The tick (counted from 1) in which something happens {@code seconds} after the start of tick {@code from + 1}. */
    private static long tickOf(long from, double seconds) {
        return from + (long) Math.ceil(seconds / Board.DEFAULT_TICK);
    }

    @Test
    void aKeyScriptPlaysTheGameAndTheReportSaysEveryHitAndDrain() throws IOException {
        Path report = directory.resolve("report.json");

        int status = run("--headless", "--ticks", "300", "--keys", file("keys.txt", SCRIPT).toString(),
                "--report", report.toString(), "--out", directory.resolve("after.txt").toString(),
                file("board.txt", BOARD).toString());

        assertThat(status).as(err.toString(StandardCharsets.UTF_8)).isEqualTo(HeadlessRunner.OK);
        JsonObject json = JsonParser.parseString(Files.readString(report)).getAsJsonObject();
        assertThat(json.get("ticks").getAsLong()).isEqualTo(300);
        assertThat(json.get("score").getAsLong()).isEqualTo(2 * 125);
        assertThat(json.get("ballsLeft").getAsInt()).isZero();
        assertThat(json.get("gameOver").getAsBoolean()).isTrue();
        JsonArray drains = json.getAsJsonArray("drains");
        assertThat(drains).hasSize(2);
        assertThat(drains.get(0).getAsJsonObject().get("tick").getAsLong()).isEqualTo(tickOf(0, 2 * FLIGHT));
        assertThat(drains.get(1).getAsJsonObject().get("tick").getAsLong()).isEqualTo(tickOf(100, 2 * FLIGHT));
        JsonArray hits = json.getAsJsonArray("scoringHits");
        assertThat(hits).hasSize(2);
        assertThat(hits.get(0).getAsJsonObject().get("tick").getAsLong()).isEqualTo(tickOf(0, FLIGHT));
        assertThat(hits.get(1).getAsJsonObject().get("tick").getAsLong()).isEqualTo(tickOf(100, FLIGHT));
        assertThat(hits.get(1).getAsJsonObject().get("gizmo").getAsString()).isEqualTo("S");
        assertThat(hits.get(1).getAsJsonObject().get("points").getAsInt()).isEqualTo(125);
        assertThat(Files.readString(directory.resolve("after.txt"))).doesNotContain("Ball B");
    }

    /** Two players, a ball each: the first launch is player 1's, the second player 2's, and the replay says so. */
    @Test
    void aGameOfTwoPlayersIsReportedPlayerByPlayerAndReplaysWithThem() throws Exception {
        Path report = directory.resolve("report.json");
        Path replay = directory.resolve("game.replay.json");
        String oneBallEach = BOARD.replace("#@Balls 2", "#@Balls 1");

        assertThat(run("--headless", "--ticks", "300", "--players", "2", "--keys", file("keys.txt", SCRIPT).toString(),
                "--report", report.toString(), "--record", replay.toString(), file("board.txt", oneBallEach).toString()))
                .as(err.toString(StandardCharsets.UTF_8)).isEqualTo(HeadlessRunner.OK);

        JsonObject json = JsonParser.parseString(Files.readString(report)).getAsJsonObject();
        assertThat(json.get("players").getAsInt()).isEqualTo(2);
        assertThat(json.getAsJsonArray("playerScores")).extracting(JsonElement::getAsLong).containsExactly(125L, 125L);
        assertThat(json.get("gameOver").getAsBoolean()).isTrue();
        assertThat(ReplayFiles.read(replay).players()).isEqualTo(2);
        out.reset();
        assertThat(run("--headless", "--replay", replay.toString())).isEqualTo(HeadlessRunner.OK);
        assertThat(out.toString(StandardCharsets.UTF_8)).isEqualTo("score 250 after 300 ticks\n");
    }

    @Test
    void aRecordedGameReplaysToItsScoreAndAChangedScoreExitsFour() throws Exception {
        Path replay = directory.resolve("game.replay.json");
        assertThat(run("--headless", "--ticks", "300", "--keys", file("keys.txt", SCRIPT).toString(),
                "--record", replay.toString(), file("board.txt", BOARD).toString())).isEqualTo(HeadlessRunner.OK);
        Replay recorded = ReplayFiles.read(replay);
        assertThat(recorded.score()).isEqualTo(250);
        assertThat(recorded.ticks()).isEqualTo(300);
        assertThat(recorded.keys().keys()).hasSize(4);
        out.reset();

        assertThat(run("--headless", "--replay", replay.toString())).isEqualTo(HeadlessRunner.OK);
        assertThat(out.toString(StandardCharsets.UTF_8)).isEqualTo("score 250 after 300 ticks\n");

        Path forged = file("forged.json", ReplayFiles.toJson(new Replay(recorded.board(), recorded.dt(),
                recorded.ticks(), recorded.keys(), 9999, 1)));
        assertThat(run("--headless", "--replay", forged.toString())).isEqualTo(HeadlessRunner.REPLAY_DIFFERS);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("the replay reaches 250, not the 9999 it recorded");
    }

    @Test
    void aBadScriptLineExitsTwoNamingTheFileAndLine() throws IOException {
        Path keys = file("keys.txt", "0 down Space\n5 sideways Space\n");

        assertThat(run("--headless", "--ticks", "10", "--keys", keys.toString(), file("board.txt", BOARD).toString()))
                .isEqualTo(HeadlessRunner.BAD_INPUT);
        assertThat(err.toString(StandardCharsets.UTF_8))
                .contains(keys + ":2: a key goes down or up, not 'sideways': 5 sideways Space");
    }

    @Test
    void aFileThatIsNoReplayExitsTwoSayingSo() throws IOException {
        assertThat(run("--headless", "--replay", file("board.txt", BOARD).toString())).isEqualTo(HeadlessRunner.BAD_INPUT);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("board.txt is not a replay file: a replay is JSON text, and this is not");
    }
}
