package gizmoball.api;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/** What the tests that read the repository's own text share: its Java files, and a file's text. */
final class SourceTexts {
    /** Where the game's and the physics library's Java sources are, tests and benchmark included. */
    static final List<Path> SOURCES = List.of(Path.of("src"), Path.of("physics-lib", "src"));

    private SourceTexts() {
    }

    /** Every Java file below the roots. */
    static List<Path> javaFiles(List<Path> roots) {
        List<Path> files = new ArrayList<>();
        for (Path root : roots) {
            try (Stream<Path> walk = Files.walk(root)) {
                walk.filter(p -> p.toString().endsWith(".java")).forEach(files::add);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return files;
    }

    static String read(Path file) {
        try {
            return Files.readString(file);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
