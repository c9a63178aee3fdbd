package gizmoball.headless;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code --headless --lab}: the same JSON file on one thread and on two, a summary line, a progress line, a heat map
 * PNG.
 */
class HeadlessLabTest {
    private static final String TABLE = """
            Absorber A 0 19 20 20
            Triangle Corner 19 0
            Rotate Corner
            LeftFlipper LF 6 16
            RightFlipper RF 10 16
            Circle C1 4 6
            Ball B 19.75 19.75 0 0
            KeyConnect key 90 down LF
            KeyConnect key 90 up LF
            KeyConnect key 47 down RF
            KeyConnect key 47 up RF
            KeyConnect key 32 down A
            #@Balls 2
            #@Drain A
            """;

    @TempDir
    Path directory;

    @Test
    void writesTheSameReportOnOneThreadAndOnTwo() throws Exception {
        Path board = Files.writeString(directory.resolve("table.txt"), TABLE);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream outStream = new PrintStream(out, true, StandardCharsets.UTF_8);
        PrintStream errStream = new PrintStream(err, true, StandardCharsets.UTF_8);
        Path one = directory.resolve("one.json");
        Path two = directory.resolve("two.json");

        assertThat(HeadlessRunner.run(List.of("--headless", "--lab", "4", "--threads", "1", "--game-cap", "60",
                "--report", one.toString(), board.toString()), outStream, errStream)).isZero();
        Path heatmap = directory.resolve("heat.png");
        assertThat(HeadlessRunner.run(List.of("--headless", "--lab", "4", "--threads", "2", "--game-cap", "60",
                "--report", two.toString(), "--heatmap", heatmap.toString(), board.toString()), outStream, errStream))
                .isZero();

        assertThat(Files.readAllBytes(two)).isEqualTo(Files.readAllBytes(one));
        String json = Files.readString(one);
        assertThat(json).contains("\"autoplayer\"", "\"idle\"", "\"secondsPerBall\"", "\"neverHit\"", "\"drains\"");
        String[] summaries = out.toString(StandardCharsets.UTF_8).split("\\R");
        assertThat(summaries).hasSize(2).allMatch(line -> line.startsWith(board + ": ") && line.contains("autoplayer mean"));
        assertThat(err.toString(StandardCharsets.UTF_8)).endsWith("lab: 8/8 games" + System.lineSeparator());
        BufferedImage picture = ImageIO.read(heatmap.toFile());
        assertThat(picture).as("a PNG at %s", heatmap).isNotNull();
        assertThat(picture.getWidth()).isEqualTo(640);
    }
}
