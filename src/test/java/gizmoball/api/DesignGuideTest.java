package gizmoball.api;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;

/**
 * docs/design.md is a guide that agrees with the code (issue 38): each section is a page at most, every class it
 * names (and every member it names of one) is in the code, and its table of the board's parts is the model package's
 * own classes, no more and no fewer.
 */
class DesignGuideTest {
    private static final Path DESIGN = Path.of("docs", "design.md");
    private static final List<Path> SOURCES = SourceTexts.SOURCES;
    private static final Path MODEL = Path.of("src", "main", "java", "gizmoball", "model");
    /** Lines of a page: a section longer than this belongs in a focused page of docs/ of its own. */
    private static final int PAGE = 60;
    /** A class in backquotes, with a member after a dot if any: {@code `Play.carryOut`}, {@code `TickRun`}. */
    private static final Pattern NAMED = Pattern.compile("`([A-Z][a-z][A-Za-z0-9]*)(?:\\.([a-zA-Z_][A-Za-z0-9_]*))?(?:\\(\\))?`");
    /** Names in backquotes that are no class of ours: the Java library's classes, the board file's word. */
    private static final Set<String> LIBRARY = Set.of("KeyEvent", "KeyEventDispatcher", "SwingWorker", "OuterWalls");

    @Test
    void everySectionIsAPageAtMost() {
        assertThat(sections(read(DESIGN))).as("sections found (not vacuous)").hasSizeGreaterThan(20);
        assertThat(tooLong(read(DESIGN))).isEmpty();
    }

    @Test
    void everyClassAndMemberItNamesIsInTheCode() {
        Map<String, String> types = declaredTypes();
        List<String> unknown = new ArrayList<>();
        Matcher m = NAMED.matcher(read(DESIGN));
        int named = 0;
        while (m.find()) {
            named++;
            String type = m.group(1);
            String member = m.group(2);
            if (LIBRARY.contains(type)) {
                continue;
            }
            String source = types.get(type);
            if (source == null) {
                unknown.add(m.group());
            } else if (member != null && !Pattern.compile("\\b" + member + "\\b").matcher(source).find()) {
                unknown.add(m.group());
            }
        }
        assertThat(named).as("names found (not vacuous)").isGreaterThan(100);
        assertThat(unknown).isEmpty();
    }

    @Test
    void theBoardsPartsAreTheModelPackagesOwnClasses() {
        String board = sections(read(DESIGN)).get("## The board");
        Set<String> listed = board.lines().filter(line -> line.startsWith("| `"))
                .map(line -> line.substring(1, line.indexOf('|', 1)))
                .flatMap(cell -> Pattern.compile("`(\\w+)`").matcher(cell).results().map(r -> r.group(1)))
                .collect(Collectors.toCollection(TreeSet::new));
        assertThat(listed).isEqualTo(packagePrivateClassesOf(MODEL));
    }

    /** The checks can fail: a long section is found, a name nobody declared is found. */
    @Test
    void theChecksFindWhatIsWrong() {
        String text = "# Title\n\n## Short\n\nOne line.\n\n## Long\n" + "A line.\n".repeat(PAGE + 1);
        assertThat(tooLong(text)).containsExactly("## Long: " + (PAGE + 1) + " lines");
        assertThat(declaredTypes()).containsKey("Board").doesNotContainKey("NoSuchClassAnywhere");
        assertThat(packagePrivateClassesOf(MODEL)).contains("Play").doesNotContain("Board");
    }

    private static List<String> tooLong(String text) {
        return sections(text).entrySet().stream().filter(e -> e.getValue().lines().count() > PAGE)
                .map(e -> e.getKey() + ": " + e.getValue().lines().count() + " lines").toList();
    }

    /** Each heading with the lines under it, up to the next heading. */
    private static Map<String, String> sections(String text) {
        Map<String, String> sections = new LinkedHashMap<>();
        String heading = null;
        StringBuilder body = new StringBuilder();
        for (String line : text.split("\n", -1)) {
            if (line.startsWith("#")) {
                if (heading != null) {
                    sections.put(heading, body.toString().strip());
                }
                heading = line;
                body.setLength(0);
            } else {
                body.append(line).append('\n');
            }
        }
        if (heading != null) {
            sections.put(heading, body.toString().strip());
        }
        return sections;
    }

    /** Every class, interface, enum and record the sources declare (nested ones too), with its file's text. */
    private static Map<String, String> declaredTypes() {
        Pattern declaration = Pattern.compile("\\b(?:class|interface|enum|record) ([A-Z][A-Za-z0-9]*)");
        Map<String, String> types = new LinkedHashMap<>();
        for (Path file : javaFiles(SOURCES)) {
            String text = read(file);
            declaration.matcher(text).results().forEach(r -> types.merge(r.group(1), text, String::concat));
        }
        return types;
    }

    /** The top-level classes of a package's folder that are not public: its own parts. */
    private static Set<String> packagePrivateClassesOf(Path folder) {
        Set<String> own = new TreeSet<>();
        for (Path file : javaFiles(List.of(folder))) {
            String name = file.getFileName().toString().replace(".java", "");
            boolean inFolder = file.getParent().equals(folder);
            Pattern topLevel = Pattern.compile("(?m)^((?:public |final |abstract |sealed )*)(?:class|interface|enum|record) "
                    + name + "\\b");
            Matcher m = topLevel.matcher(read(file));
            if (inFolder && m.find() && !m.group(1).contains("public")) {
                own.add(name);
            }
        }
        return own;
    }

    private static List<Path> javaFiles(List<Path> roots) {
        return SourceTexts.javaFiles(roots);
    }

    private static String read(Path file) {
        return SourceTexts.read(file);
    }
}
