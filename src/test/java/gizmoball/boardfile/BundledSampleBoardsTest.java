package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** The sample boards inside the game are boards/ as it is, and each loads without a bad line. */
class BundledSampleBoardsTest {
    @Test
    void theSamplesAreTheBoardsFolder() throws Exception {
        List<String> boards;
        try (Stream<Path> files = Files.list(Path.of("boards"))) {
            boards = files.map(f -> f.getFileName().toString()).sorted().toList();
        }
        assertThat(SampleBoards.names()).containsExactlyElementsOf(boards);
        for (String name : boards) {
            assertThat(SampleBoards.text(name)).contains(Files.readString(Path.of("boards", name)));
            assertThat(BoardFiles.loadSkippingBadLines(name, SampleBoards.text(name).orElseThrow()).skippedLines())
                    .isEmpty();
        }
    }

    @Test
    void anUnknownSampleIsNone() {
        assertThat(SampleBoards.text("no-such.txt")).isEmpty();
        assertThat(SampleBoards.text("../version.txt")).isEmpty();
    }
}
