package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * The project's own corpus (src/test/resources/dialect-boards): one file per group of dialect features the
 * loader tolerates (docs/board-files.md, "What the loader tolerates"), plus files with bad lines. Besides the corpus
 * checks, each tolerant file X.txt must mean exactly what X.canonical, its hand-written canonical form, says.
 */
class DialectBoardsTest extends BoardCorpusTest {
    private static final String CANONICAL = ".canonical";

    @Override
    Path folder() {
        try {
            return Path.of(DialectBoardsTest.class.getResource("/dialect-boards").toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    @Override
    String table() {
        return "/dialect-boards-expected.tsv";
    }

    @Override
    boolean isBoard(Path file) {
        return file.getFileName().toString().endsWith(".txt");
    }

    @TestFactory
    Stream<DynamicTest> eachTolerantFileMeansItsCanonicalForm() throws IOException {
        try (Stream<Path> files = Files.list(folder())) {
            return files.filter(f -> f.getFileName().toString().endsWith(CANONICAL)).sorted().toList().stream()
                    .map(canonical -> DynamicTest.dynamicTest(canonical.getFileName().toString(), () -> {
                        String name = canonical.getFileName().toString();
                        Path board = canonical.resolveSibling(name.substring(0, name.length() - CANONICAL.length())
                                + ".txt");
                        assertThat(BoardWriter.toText(BoardFiles.load(board)))
                                .isEqualTo(Files.readString(canonical, StandardCharsets.UTF_8));
                    }));
        }
    }
}
