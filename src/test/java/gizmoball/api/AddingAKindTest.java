package gizmoball.api;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

/**
 * docs/design.md, "Adding a gizmo kind", names every file a new kind touches: every file of the game that names each
 * of the extension kinds (by its GizmoKind constant or its class) is one a new kind would be added to, and
 * it is in the list; every file the list names exists.
 */
class AddingAKindTest {
    private static final Path MAIN = Path.of("src", "main", "java", "gizmoball");
    /** The kinds this game added to the standard five: each is named where a new kind must be. */
    private static final List<String> EXTENSION_KINDS = List.of("SINK", "ACCELERATOR", "SPAWNER", "GATE",
            "DROP_TARGET", "PORTAL", "SPINNER");
    /** A file's path relative to gizmoball/, in backquotes: {@code `view/GizmoArt.java`}. */
    private static final Pattern LISTED_FILE = Pattern.compile("`([\\w/<>]+\\.java)`");

    @Test
    void everyFileThatNamesEachExtensionKindIsListedAndEveryListedFileExists() {
        Set<String> listed = listedFiles();
        List<String> perKind = new ArrayList<>();
        for (Path file : SourceTexts.javaFiles(List.of(MAIN))) {
            String text = SourceTexts.read(file);
            if (EXTENSION_KINDS.stream().allMatch(kind -> names(text, kind))) {
                perKind.add(MAIN.relativize(file).toString().replace('\\', '/'));
            }
        }
        // Not vacuous: the kinds' own home and their views' sealed list name each of them, however few others do.
        assertThat(perKind).as("files naming every extension kind").contains("model/gizmo/GizmoKind.java",
                "model/gizmo/Gizmo.java");
        assertThat(listed).as("design.md, \"Adding a gizmo kind\"").containsAll(perKind);
        listed.stream().filter(f -> !f.contains("<Kind>"))
                .forEach(f -> assertThat(MAIN.resolve(f)).as("listed file").isRegularFile());
    }

    /** The check can fail: a file naming only some of the kinds is not a per-kind file. */
    @Test
    void aFileNamingOnlySomeKindsIsNotOne() {
        assertThat(names("case GATE -> x;", "GATE")).isTrue();
        assertThat(names("new DropTarget(name)", "DROP_TARGET")).isTrue();
        assertThat(names("a gate's hinge", "GATE")).isFalse();
        assertThat(EXTENSION_KINDS.stream().allMatch(k -> names("case GATE, SINK -> x;", k))).isFalse();
    }

    /** Whether the text names the kind: its constant, or its class or view as a word. */
    private static boolean names(String text, String kind) {
        return Pattern.compile("\\b" + kind + "\\b|\\b" + camel(kind) + "(View)?\\b").matcher(text).find();
    }

    /** DROP_TARGET -> DropTarget. */
    private static String camel(String constant) {
        StringBuilder out = new StringBuilder();
        for (String part : constant.split("_")) {
            out.append(part.charAt(0)).append(part.substring(1).toLowerCase(Locale.ROOT));
        }
        return out.toString();
    }

    private static Set<String> listedFiles() {
        String design = SourceTexts.read(Path.of("docs", "design.md"));
        int start = design.indexOf("## Adding a gizmo kind");
        assertThat(start).as("the section").isNotNegative();
        int end = design.indexOf("\n## ", start + 1);
        Matcher m = LISTED_FILE.matcher(design.substring(start, end < 0 ? design.length() : end));
        Set<String> files = new LinkedHashSet<>();
        while (m.find()) {
            files.add(m.group(1));
        }
        return files;
    }
}
