package gizmoball.boardfile;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Optional;

/**
 * The sample boards that ship inside the game (the build copies boards/ into the resources, with an index,
 * since a jar's folders cannot be listed), so that a player with nothing but the jar has boards to play.
 */
public final class SampleBoards {
    private static final String FOLDER = "/gizmoball/samples/";

    private SampleBoards() {
    }

    /** The file names of the samples, e.g. "default.txt"; empty when the game was not built with them. */
    public static List<String> names() {
        return read("index.txt").map(index -> index.lines().map(String::strip).filter(s -> !s.isEmpty()).toList())
                .orElse(List.of());
    }

    /** The text of one sample board. */
    public static Optional<String> text(String name) {
        return names().contains(name) ? read(name) : Optional.empty();
    }

    private static Optional<String> read(String name) {
        try (InputStream in = SampleBoards.class.getResourceAsStream(FOLDER + name)) {
            return in == null ? Optional.empty() : Optional.of(new String(in.readAllBytes(), StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the sample board " + name + " inside the game", e);
        }
    }
}
