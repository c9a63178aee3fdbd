package gizmoball;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A new JVM started from a test, as a player's shell would start it, but without the JVM options that the test's
 * own environment may hold: with {@code JAVA_TOOL_OPTIONS} (or {@code _JAVA_OPTIONS}, {@code JDK_JAVA_OPTIONS}) set,
 * the JVM prints "Picked up ..." before the program says a word, and a check of the program's exact output would
 * read the JVM's line instead.
 */
public final class ChildJvm {
    /** The variables through which the environment adds options to every JVM it starts. */
    public static final List<String> OPTION_VARIABLES = List.of("JAVA_TOOL_OPTIONS", "_JAVA_OPTIONS", "JDK_JAVA_OPTIONS");

    private ChildJvm() {
    }

    /** {@code java args...} with this JVM's own java, the environment's JVM options removed. */
    public static ProcessBuilder java(List<String> args) {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.addAll(args);
        ProcessBuilder builder = new ProcessBuilder(command);
        OPTION_VARIABLES.forEach(builder.environment()::remove);
        return builder;
    }
}
