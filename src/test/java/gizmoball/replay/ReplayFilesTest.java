package gizmoball.replay;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Issue 40 item 8: a file that is no replay, or not a whole one, says what is wrong in a player's words. */
class ReplayFilesTest {
    private static final String WHOLE = """
            {"format": "gizmoball replay", "version": 1, "board": "Gravity 25.0\\n", "dt": 0.016666666666666666,
             "ticks": 10, "score": 0, "keys": []}
            """;

    @TempDir
    Path dir;

    private String whyNot(Path file) {
        return catchThrowableOfType(() -> ReplayFiles.read(file), ReplayFiles.BadReplay.class).getMessage();
    }

    @Test
    void aWholeReplayReads() throws Exception {
        assertThat(ReplayFiles.read(Files.writeString(dir.resolve("r.json"), WHOLE)).ticks()).isEqualTo(10);
    }

    @Test
    void bytesThatAreNoTextAreNoReplay() throws Exception {
        Path junk = Files.write(dir.resolve("junk.json"), new byte[] {(byte) 0xff, (byte) 0xfe, 0, 1, 2});
        assertThat(whyNot(junk)).isEqualTo(junk + " is not a replay file: it is not text (it holds bytes that are not"
                + " UTF-8)");
    }

    @Test
    void textThatIsNoJsonIsNoReplay() throws Exception {
        Path board = Files.writeString(dir.resolve("board.txt"), "Square S 1 1\nGravity 25\n");
        assertThat(whyNot(board)).isEqualTo(board + " is not a replay file: a replay is JSON text, and this is not");
    }

    @Test
    void jsonOfSomethingElseIsNoReplay() throws Exception {
        Path other = Files.writeString(dir.resolve("other.json"), "{\"name\": \"Ada\"}");
        assertThat(whyNot(other)).isEqualTo(other + " is not a replay file: it does not say \"format\": \"gizmoball"
                + " replay\"");
    }

    @Test
    void aReplayWithoutItsBoardSaysWhichFieldIsMissingAndWhatItIs() throws Exception {
        Path part = Files.writeString(dir.resolve("part.json"), WHOLE.replace("\"board\": \"Gravity 25.0\\n\", ", ""));
        assertThat(whyNot(part)).isEqualTo(part + " is not a whole replay: it has no \"board\" (the board it was"
                + " played on)");
    }
}
