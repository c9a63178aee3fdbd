package gizmoball.api;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

/**
 * A house that stays small as it grows (issue 38): no class of the game or of physics-lib is over {@link #MOST} lines,
 * and one over {@link #WITHOUT_REASON} says at its head, in a line, why it is one class ("Over 400 lines because ...").
 */
class ClassSizeTest {
    private static final List<Path> MAIN = List.of(Path.of("src", "main", "java"),
            Path.of("physics-lib", "src", "main", "java"));
    private static final int MOST = 500;
    private static final int WITHOUT_REASON = 400;
    private static final String REASON = WITHOUT_REASON + " lines because";
    /** The head of a file: what comes before its top-level type's declaration. */
    private static final Pattern DECLARATION = Pattern.compile(
            "(?m)^(?:public |final |abstract |sealed |non-sealed )*(?:class|interface|enum|record) ");
    /** A line of the head that says why: it names the 400 lines and gives a reason. */
    private static final Pattern REASON_LINE = Pattern.compile("(?m)^.*" + WITHOUT_REASON + " lines\\b.*\\bbecause\\b.*$");

    @Test
    void everyClassIsSmallOrSaysWhyItIsOne() {
        List<Path> files = SourceTexts.javaFiles(MAIN);
        assertThat(files).as("source files found (not vacuous)").hasSizeGreaterThan(200);
        List<String> problems = new ArrayList<>();
        for (Path file : files) {
            problem(file.toString(), SourceTexts.read(file)).ifPresent(problems::add);
        }
        assertThat(problems).isEmpty();
    }

    /** The check can fail: a long class is named, a longer one without its reason too. */
    @Test
    void aLongClassIsFound() {
        String body = "    int x;\n".repeat(WITHOUT_REASON);
        assertThat(problem("Small.java", "/** One job. */\nclass Small {\n}\n")).isEmpty();
        assertThat(problem("Long.java", "/** One job. */\nclass Long {\n" + body + "}\n")).isPresent();
        assertThat(problem("Said.java", "/** Over " + REASON + " it is one solver. */\nclass Said {\n" + body + "}\n"))
                .isEmpty();
        assertThat(problem("Huge.java", "/** Over " + REASON + " no. */\nclass Huge {\n" + body + body + "}\n"))
                .isPresent();
    }

    /** What is wrong with the file's size, if anything. */
    private static Optional<String> problem(String name, String text) {
        long lines = text.lines().count();
        if (lines > MOST) {
            return Optional.of(name + ": " + lines + " lines, over " + MOST);
        }
        Matcher declaration = DECLARATION.matcher(text);
        boolean reasoned = declaration.find() && REASON_LINE.matcher(text.substring(0, declaration.start())).find();
        if (lines > WITHOUT_REASON && !reasoned) {
            return Optional.of(name + ": " + lines + " lines, over " + WITHOUT_REASON + " without a reason at its head");
        }
        return Optional.empty();
    }
}
