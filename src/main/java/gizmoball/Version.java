package gizmoball;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;

/** The game's version, as the build wrote it into the resources (build.gradle's {@code version}). */
public final class Version {
    private static final String RESOURCE = "/gizmoball/version.txt";

    private Version() {
    }

    /** E.g. "1.0.0"; "unknown" when the classes were not built by the project's build. */
    public static String current() {
        try (InputStream in = Version.class.getResourceAsStream(RESOURCE)) {
            return in == null ? "unknown" : new String(in.readAllBytes(), StandardCharsets.UTF_8).strip();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the game's version", e);
        }
    }
}
