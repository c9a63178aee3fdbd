package gizmoball.api;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * A kind stays small as the game grows (issue 38): each gizmo kind is named in code by at most {@link #MOST} files of
 * the game, its own class and view, its constant's home and one line per layer among them. A file names a kind when,
 * its comments left out, it has the kind's {@link GizmoKind} constant (or the command word's of the same name), the
 * class that plays it or that class's view, or the kind's command word in quotes ({@code "DropTarget"}). Words in
 * comments are not names in code, and physics-lib's {@code Circle} is not the circle bumper, whose class is
 * {@code Bumper}.
 */
class FilesPerKindTest {
    private static final Path MAIN = Path.of("src", "main", "java", "gizmoball");
    private static final Path GIZMO_PACKAGE = MAIN.resolve(Path.of("model", "gizmo"));
    /** The most files of the game that may name one kind. */
    private static final int MOST = 12;

    @Test
    void everyKindIsNamedByFewFilesOfTheGame() {
        Map<Path, String> code = SourceTexts.javaFiles(List.of(MAIN)).stream()
                .collect(Collectors.toMap(file -> file, file -> withoutComments(SourceTexts.read(file))));
        List<String> over = new ArrayList<>();
        for (GizmoKind kind : GizmoKind.values()) {
            Pattern names = namesOf(kind);
            List<String> naming = code.entrySet().stream().filter(e -> names.matcher(e.getValue()).find())
                    .map(e -> MAIN.relativize(e.getKey()).toString().replace('\\', '/')).sorted().toList();
            assertThat(naming).as("files naming %s (not vacuous: its own class at least)", kind).isNotEmpty();
            if (naming.size() > MOST) {
                over.add(kind + " is named by " + naming.size() + " files, at most " + MOST + ": " + naming);
            }
        }
        assertThat(over).isEmpty();
    }

    /** The check can fail: a name in code counts, the same word in a comment or as part of a longer name does not. */
    @Test
    void aNameInCodeCountsAndAWordInACommentDoesNot() {
        Pattern sink = namesOf(GizmoKind.SINK);
        assertThat(sink.matcher(withoutComments("case SINK -> 1;")).find()).isTrue();
        assertThat(sink.matcher(withoutComments("void take(Sink sink)")).find()).isTrue();
        assertThat(sink.matcher(withoutComments("String word = \"Sink\";")).find()).isTrue();
        assertThat(sink.matcher(withoutComments("// a Sink takes it\n/* SINK */ int x;")).find()).isFalse();
        assertThat(sink.matcher(withoutComments("interface KeySink {}")).find()).isFalse();
        Pattern circle = namesOf(GizmoKind.CIRCLE);
        assertThat(circle.matcher("import physics.Circle;").find()).isFalse();
        assertThat(circle.matcher("(BumperView) gizmo").find()).isTrue();
        assertThat(withoutComments("String s = \"// not a comment\"; // a comment"))
                .isEqualTo("String s = \"// not a comment\"; ");
    }

    /**
     * The names of a kind in code: its constant, its command word in quotes, its class and view (the class of its own
     * name if there is one, and the class it is played by with the views that class answers as).
     */
    private static Pattern namesOf(GizmoKind kind) {
        Set<String> classes = new LinkedHashSet<>();
        String own = camel(kind.name());
        if (Files.exists(GIZMO_PACKAGE.resolve(own + ".java"))) {
            classes.add(own);
        }
        if (!kind.sizedByCorners()) {   // one made from its corners is of its own class (its create refuses a cell)
            Class<?> played = kind.create("x", 0, 0).getClass();
            classes.add(played.getSimpleName());
            Arrays.stream(played.getInterfaces()).filter(Gizmo.class::isAssignableFrom)
                    .forEach(view -> classes.add(view.getSimpleName()));
        }
        if (classes.contains(own)) {
            classes.add(own + "View");
        }
        String alternatives = Stream.concat(Stream.of(kind.name()), classes.stream()).map(name -> "\\b" + name + "\\b")
                .collect(Collectors.joining("|"));
        return Pattern.compile(alternatives + "|\"" + own + "\"");
    }

    /** DROP_TARGET -> DropTarget (the class's name and the command word's spelling). */
    private static String camel(String constant) {
        StringBuilder out = new StringBuilder();
        for (String part : constant.split("_")) {
            out.append(part.charAt(0)).append(part.substring(1).toLowerCase(Locale.ROOT));
        }
        return out.toString();
    }

    /** Java source without its comments; string and character literals (text blocks too) kept as they are. */
    static String withoutComments(String source) {
        StringBuilder out = new StringBuilder(source.length());
        int i = 0;
        while (i < source.length()) {
            if (source.startsWith("//", i)) {
                int end = source.indexOf('\n', i);
                i = end < 0 ? source.length() : end;
            } else if (source.startsWith("/*", i)) {
                int end = source.indexOf("*/", i + 2);
                i = end < 0 ? source.length() : end + 2;
            } else if (source.startsWith("\"\"\"", i)) {
                int end = source.indexOf("\"\"\"", i + 3) + 3;
                out.append(source, i, end);
                i = end;
            } else if (source.charAt(i) == '"' || source.charAt(i) == '\'') {
                int end = literalEnd(source, i);
                out.append(source, i, end);
                i = end;
            } else {
                out.append(source.charAt(i++));
            }
        }
        return out.toString();
    }

    /** Just past the closing quote of the string or character literal that opens at {@code start}. */
    private static int literalEnd(String source, int start) {
        char quote = source.charAt(start);
        int i = start + 1;
        while (source.charAt(i) != quote) {
            i += source.charAt(i) == '\\' ? 2 : 1;
        }
        return i + 1;
    }
}
