package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.fail;

import gizmoball.model.Board;
import gizmoball.model.Invariants;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * Every board written by another implementation (../shared/peer-boards, the project's sibling) either loads or
 * is refused with line-numbered reasons, and the outcome of each is pinned in peer-boards-expected.tsv so that a
 * change in either direction (a file newly refused, or newly accepted) fails here. Every loadable one then runs
 * 2,000 ticks with the model's invariants holding (balls the file placed on each other may overlap until they
 * have separated once).
 */
class PeerBoardsTest {
    private static final Path PEER_BOARDS = Path.of(System.getProperty("user.dir")).toAbsolutePath()
            .resolveSibling("shared").resolve("peer-boards");
    private static final Set<String> NOT_BOARDS = Set.of("README.md", "SOURCES.tsv");
    private static final String TABLE = "/peer-boards-expected.tsv";
    private static final int TICKS = 2_000;

    /** How a file loads: strictly, only with some lines skipped (leaving a non-empty board), or not at all. */
    record Outcome(String kind, int skippedLines, String firstReason) {
        static Outcome of(LoadResult result) {
            List<BoardFileError> skipped = result.skippedLines();
            if (skipped.isEmpty()) {
                return new Outcome("strict", 0, "");
            }
            boolean empty = result.board().gizmos().isEmpty() && result.board().balls().isEmpty();
            BoardFileError first = skipped.get(0);
            return new Outcome(empty ? "refused" : "skipped-lines", skipped.size(), first.line() + ": " + first.reason());
        }

        boolean loadable() {
            return !kind.equals("refused");
        }
    }

    @Test
    void theTableNamesExactlyTheFilesThatAreThere() throws IOException {
        assertThat(new TreeSet<>(expected().keySet())).isEqualTo(new TreeSet<>(peerFiles().stream()
                .map(p -> p.getFileName().toString()).toList()));
    }

    @TestFactory
    Stream<DynamicTest> everyFileLoadsOrIsRefusedLineByLineAsPinned() throws IOException {
        Map<String, Outcome> expected = expected();
        return peerFiles().stream().map(file -> DynamicTest.dynamicTest(file.getFileName().toString(), () -> {
            String name = file.getFileName().toString();
            String text = new String(Files.readAllBytes(file), StandardCharsets.UTF_8);
            LoadResult skipping = BoardFiles.loadSkippingBadLines(file);
            List<String> lines = List.of(text.split("\n", -1));
            for (BoardFileError error : skipping.skippedLines()) {
                assertThat(error.line()).as(name).isBetween(1, lines.size());
                assertThat(error.text()).as(name).isEqualTo(lines.get(error.line() - 1).replace("\r", ""));
                assertThat(error.reason()).as(name).isNotBlank();
            }
            try {
                BoardFiles.load(file);
                assertThat(skipping.skippedLines()).as(name + " loaded strictly").isEmpty();
            } catch (BoardFileException refused) {
                assertThat(refused.errors()).as(name).isEqualTo(skipping.skippedLines());
            }
            assertThat(Outcome.of(skipping)).as(name).isEqualTo(expected.get(name));
        }));
    }

    @TestFactory
    Stream<DynamicTest> everyLoadableFileRunsWithTheInvariantsHolding() throws IOException {
        Map<String, Outcome> expected = expected();
        return peerFiles().stream()
                .filter(file -> expected.getOrDefault(file.getFileName().toString(), new Outcome("refused", 0, ""))
                        .loadable())
                .map(file -> DynamicTest.dynamicTest(file.getFileName().toString(), () -> {
                    Board board = BoardFiles.loadSkippingBadLines(file).board();
                    PassingPairs passing = new PassingPairs(board);
                    assertThat(Invariants.violations(board, passing.pairs())).as("as loaded").isEmpty();
                    for (int tick = 1; tick <= TICKS; tick++) {
                        board.tick(Board.DEFAULT_TICK);
                        passing.update(board);
                        List<String> violations = Invariants.violations(board, passing.pairs());
                        if (!violations.isEmpty()) {
                            fail("after tick " + tick + ": " + violations);
                        }
                    }
                }));
    }

    private static List<Path> peerFiles() throws IOException {
        assertThat(PEER_BOARDS).as("the peer boards corpus should be the project's sibling folder " + PEER_BOARDS)
                .isDirectory();
        try (Stream<Path> files = Files.list(PEER_BOARDS)) {
            return files.filter(p -> !NOT_BOARDS.contains(p.getFileName().toString())).sorted().toList();
        }
    }

    /** file -> outcome, from the tab-separated table: file, strict|skipped-lines|refused, lines skipped, first reason. */
    private static Map<String, Outcome> expected() throws IOException {
        Map<String, Outcome> table = new LinkedHashMap<>();
        try (InputStream in = PeerBoardsTest.class.getResourceAsStream(TABLE)) {
            assertThat(in).as(TABLE + " on the test class path").isNotNull();
            for (String line : new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().toList()) {
                if (line.isBlank() || line.startsWith("#")) {
                    continue;
                }
                String[] columns = line.split("\t", -1);
                assertThat(columns).as(line).hasSize(4);
                table.put(columns[0], new Outcome(columns[1], Integer.parseInt(columns[2]), columns[3]));
            }
        }
        return table;
    }
}
