package gizmoball.api;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

/**
 * What the code cites is in the repository (docs/design.md, "What the code cites"): every document a source file
 * names under docs/ exists, every section it names there ({@code docs/design.md, "The tick"}) is a heading of that
 * document or a paragraph's bold heading (or the start of one), and nothing cites the product description's own
 * file, which is not here (docs/rules.md restates the rules the code cites).
 */
class CitationsTest {
    private static final List<Path> SOURCES = SourceTexts.SOURCES;
    /** A document under docs/, and the section that follows it in quotes, if any. */
    private static final Pattern CITATION = Pattern.compile("docs/([\\w-]+\\.(?:md|txt))(?:, \"([^\"]+)\")?");
    private static final Pattern PRODUCT_FILE = Pattern.compile("\\bSPEC(\\.md)?\\b");

    @Test
    void everyCitedDocumentAndSectionIsInTheRepository() {
        List<String> missing = new ArrayList<>();
        int sections = 0;
        for (Path file : sourceFiles()) {
            Matcher m = CITATION.matcher(read(file));
            while (m.find()) {
                Path doc = Path.of("docs", m.group(1));
                if (!Files.isRegularFile(doc)) {
                    missing.add(file + ": no " + doc);
                } else if (m.group(2) != null) {
                    sections++;
                    // A section's name may run over a comment's line break.
                    String section = m.group(2).replaceAll("\\s*\\n\\s*(\\*\\s*|//\\s*)?", " ");
                    if (!hasHeading(doc, section)) {
                        missing.add(file + ": no section \"" + section + "\" in " + doc);
                    }
                }
            }
        }
        assertThat(sections).as("section citations found (not vacuous)").isGreaterThan(20);
        assertThat(missing).isEmpty();
    }

    @Test
    void nothingCitesTheProductDescriptionsOwnFile() {
        List<String> citing = sourceFiles().stream()
                .filter(file -> !file.endsWith("CitationsTest.java") && PRODUCT_FILE.matcher(read(file)).find())
                .map(Path::toString).toList();
        assertThat(citing).isEmpty();
    }

    /** The checks can fail: a made-up section is not a heading, a real one (or its start) is. */
    @Test
    void aSectionThatIsNoHeadingIsFound() {
        Path design = Path.of("docs", "design.md");
        assertThat(hasHeading(design, "The tick")).isTrue();
        assertThat(hasHeading(design, "Failure modes")).isTrue();
        assertThat(hasHeading(design, "A section nobody wrote")).isFalse();
    }

    /** A heading ("## The tick") or a paragraph's bold run-in heading ("**What the loader tolerates**, ..."). */
    private static boolean hasHeading(Path doc, String section) {
        return read(doc).lines().anyMatch(line -> line.startsWith("**" + section)
                || line.matches("#+ .*") && line.replaceFirst("#+ ", "").startsWith(section));
    }

    private static List<Path> sourceFiles() {
        List<Path> files = SourceTexts.javaFiles(SOURCES);
        assertThat(files).as("source files found").hasSizeGreaterThan(100);
        return files;
    }

    private static String read(Path file) {
        return SourceTexts.read(file);
    }
}
