package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

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
 * A folder of board files each of which either loads or is refused with line-numbered reasons, the outcome of
 * each pinned in a table so that a change in either direction (a file newly refused, or newly accepted) fails
 * here. Every loadable one then runs 2,000 ticks with the model's invariants holding (balls the file placed on
 * each other may overlap until they have separated once). Two corpora:
 * {@link DialectBoardsTest}, the project's own files (every dialect feature the loader tolerates), and
 * {@link PeerBoardsTest}, the boards of other implementations beside the repository.
 */
abstract class BoardCorpusTest {
    private static final Set<String> NOT_BOARDS = Set.of("README.md", "SOURCES.tsv");
    private static final int TICKS = 2_000;

    /** The folder of board files (the test skips, saying why, when it is not there). */
    abstract Path folder();

    /** The class-path resource holding the table of pinned outcomes. */
    abstract String table();

    /** Whether a file of the folder is a board of the corpus (the folder may hold other files). */
    boolean isBoard(Path file) {
        return !NOT_BOARDS.contains(file.getFileName().toString());
    }

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
        assertThat(new TreeSet<>(expected().keySet())).isEqualTo(new TreeSet<>(boardFiles().stream()
                .map(p -> p.getFileName().toString()).toList()));
    }

    @TestFactory
    Stream<DynamicTest> everyFileLoadsOrIsRefusedLineByLineAsPinned() throws IOException {
        Map<String, Outcome> expected = expected();
        return boardFiles().stream().map(file -> DynamicTest.dynamicTest(file.getFileName().toString(), () -> {
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
        return boardFiles().stream()
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

    final List<Path> boardFiles() throws IOException {
        Path folder = folder();
        assumeTrue(Files.isDirectory(folder), () -> "no board corpus at " + folder.toAbsolutePath().normalize());
        try (Stream<Path> files = Files.list(folder)) {
            return files.filter(this::isBoard).sorted().toList();
        }
    }

    /** file -> outcome, from the tab-separated table: file, strict|skipped-lines|refused, lines skipped, first reason. */
    private Map<String, Outcome> expected() throws IOException {
        Map<String, Outcome> table = new LinkedHashMap<>();
        try (InputStream in = BoardCorpusTest.class.getResourceAsStream(table())) {
            assertThat(in).as(table() + " on the test class path").isNotNull();
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
