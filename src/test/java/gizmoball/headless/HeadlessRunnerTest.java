package gizmoball.headless;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.offset;

import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.loop.BallView;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class HeadlessRunnerTest {
    @TempDir
    Path directory;

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int run(String... args) {
        return HeadlessRunner.run(List.of(args), new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    private String stdout() {
        return out.toString(StandardCharsets.UTF_8);
    }

    private String stderr() {
        return err.toString(StandardCharsets.UTF_8);
    }

    private Path board(String text) throws IOException {
        return Files.writeString(directory.resolve("board.txt"), text);
    }

    @Test
    void movesABallWithoutForcesAtItsConstantVelocity() throws Exception {
        // No gravity, no friction, nothing to hit: after 60 ticks of 1/120 s the ball has moved v * 0.5 s.
        Path file = board("Gravity 0\nFriction 0 0\nBall B 5 5 4 -2\n");

        assertThat(run("--headless", "--ticks", "60", "--dt", String.valueOf(1.0 / 120), file.toString())).isZero();

        BallView ball = BoardFiles.load("stdout", stdout()).ball("B").orElseThrow();
        assertThat(ball.position().x()).isCloseTo(7.0, offset(1e-9));
        assertThat(ball.position().y()).isCloseTo(4.0, offset(1e-9));
        assertThat(ball.velocity().x()).isEqualTo(4.0);
        assertThat(stderr()).isEmpty();
    }

    @Test
    void zeroTicksWritesTheBoardBackInCanonicalForm() throws Exception {
        Path file = board("square S 1 2\r\nCIRCLE C 3 4\r\n");
        assertThat(run("--headless", "--ticks", "0", file.toString())).isZero();
        assertThat(stdout()).isEqualTo("Square S 1 2\nCircle C 3 4\nGravity 25.0\nFriction 0.025 0.025\n");
    }

    @Test
    void writesToTheOutFileInsteadOfStandardOutput() throws Exception {
        Path file = board("Ball B 10 10 0 0\n");
        Path result = directory.resolve("after.txt");
        assertThat(run("--headless", "--ticks", "30", "--out", result.toString(), file.toString())).isZero();
        assertThat(stdout()).isEmpty();
        Board after = BoardFiles.load(result);
        // From rest, gravity first then motion each tick: without friction it falls g dt^2 n(n+1)/2;
        // friction (at most about 8% over these 0.5 s) only shortens that.
        double frictionless = 25 * Board.DEFAULT_TICK * Board.DEFAULT_TICK * 30 * 31 / 2;
        assertThat(after.ball("B").orElseThrow().position().y()).isBetween(10 + 0.9 * frictionless, 10 + frictionless);
        assertThat(after.ball("B").orElseThrow().velocity().y()).isPositive();
    }

    @Test
    void aBadBoardExitsTwoWithEveryBadLineOnStandardError() throws Exception {
        Path file = board("Square S 1 1\nSquare S 2 2\nRhombus X 1 1\n");
        assertThat(run("--headless", "--ticks", "10", file.toString())).isEqualTo(HeadlessRunner.BAD_INPUT);
        assertThat(stdout()).isEmpty();
        assertThat(stderr()).contains(file + ":2: name S is already used: Square S 2 2",
                file + ":3: Rhombus X: an extension of another implementation, not part of the format: Rhombus X 1 1");
    }

    @Test
    void skippingBadLinesRunsTheRestAndReportsWhatWasSkipped() throws Exception {
        Path file = board("Square S 1 1\nColor S red\nCircle C 5 5\n");
        assertThat(run("--headless", "--skip-bad-lines", "--ticks", "1", file.toString())).isZero();
        assertThat(stderr()).isEqualTo("skipped " + file
                + ":2: colour 'red' is neither #rrggbb nor a 32-bit ARGB number: Color S red" + System.lineSeparator());
        assertThat(stdout()).startsWith("Square S 1 1\nCircle C 5 5\n");
    }

    @Test
    void aMissingBoardExitsTwo() {
        assertThat(run("--headless", "--ticks", "1", directory.resolve("none.txt").toString()))
                .isEqualTo(HeadlessRunner.BAD_INPUT);
        assertThat(stderr()).contains("cannot read " + directory.resolve("none.txt") + ": there is no such file");
    }

    @Test
    void badArgumentsExitTwoWithTheUsage() {
        assertThat(run("--headless", "board.txt")).isEqualTo(HeadlessRunner.BAD_INPUT);
        assertThat(stderr()).contains("--ticks N is required", HeadlessOptions.USAGE);
    }

    @Test
    void aFailedWriteExitsThreeAndLeavesTheOldFile() throws Exception {
        Path file = board("Ball B 10 10 0 0\n");
        Path result = directory.resolve("after");
        Files.createDirectory(result);
        Files.writeString(result.resolve("keep"), "kept");
        assertThat(run("--headless", "--ticks", "1", "--out", result.toString(), file.toString()))
                .isEqualTo(HeadlessRunner.WRITE_FAILED);
        assertThat(stderr()).contains("cannot save " + result + ": it is a folder");
        assertThat(Files.readString(result.resolve("keep"))).isEqualTo("kept");
    }

    @Test
    void writingIntoAMissingFolderSaysSoInTheWindowsWords() throws Exception {
        Path file = board("Ball B 10 10 0 0\n");
        Path result = directory.resolve("no-such-dir").resolve("after.txt");
        assertThat(run("--headless", "--ticks", "1", "--out", result.toString(), file.toString()))
                .isEqualTo(HeadlessRunner.WRITE_FAILED);
        assertThat(stderr()).isEqualTo("gizmoball: cannot save " + result + ": the folder "
                + directory.resolve("no-such-dir") + " does not exist" + System.lineSeparator());
    }
}
