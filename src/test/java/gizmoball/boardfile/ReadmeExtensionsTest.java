package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.GizmoKind;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Issue 40 item 15: the README's extension gizmos are a table that reads at a glance, a row for every gizmo the
 * game adds to the format, naming its line; and the prose around it keeps to the width of the other paragraphs.
 */
class ReadmeExtensionsTest {
    private static final int WIDEST_LINE = 120;

    private static List<String> readme() throws IOException {
        return Files.readAllLines(Path.of("README.md"));
    }

    @Test
    void everyGizmoTheGameAddsHasARowNamingItsLine() throws IOException {
        List<String> rows = readme().stream().filter(line -> line.startsWith("| ")).toList();
        for (GizmoKind kind : Arrays.stream(GizmoKind.values()).filter(k -> CommandWord.of(k).ours()).toList()) {
            assertThat(rows).as(kind + "'s row").anyMatch(row -> row.startsWith("| " + kind.displayName() + " | `"
                    + CommandWord.OURS + CommandWord.of(kind).spelling() + "`"));
        }
    }

    @Test
    void thePartOnTheGamesAdditionsKeepsToTheWidthOfTheRest() throws IOException {
        List<String> lines = readme();
        int from = lines.indexOf("This game adds gizmos of its own, written on `#@` lines that other programs skip as"
                + " comments:");
        int to = lines.indexOf("## Develop");
        assertThat(from).as("the part on the game's additions").isNotNegative().isLessThan(to);
        for (String line : lines.subList(from, to)) {
            if (!line.startsWith("|")) {
                assertThat(line.length()).as(line).isLessThanOrEqualTo(WIDEST_LINE);
            }
        }
    }
}
