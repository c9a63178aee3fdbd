package gizmoball;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The runnable jar (`gradle jar`), started as a player would start it: {@code java -jar gizmoball-V.jar}. */
class JarTest {
    private static final String JAR_PROPERTY = "gizmoball.jar";

    @TempDir
    Path dir;
    private Path jar;

    private record Result(int status, String out, String err) {
    }

    @BeforeEach
    void findTheJar() {
        String path = System.getProperty(JAR_PROPERTY);
        assumeTrue(path != null, "jar test skipped: run by `gradle test`, which builds the jar and passes -D"
                + JAR_PROPERTY);
        jar = Path.of(path);
        assertThat(jar).as("the jar gradle built").isRegularFile();
    }

    /** Runs the jar in a new JVM in an empty folder (no boards/ near), with {@code env} changes. */
    private Result java(Map<String, String> env, String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of(
                "-Djava.util.prefs.userRoot=" + dir.resolve("prefs"), "-jar", jar.toString()));
        command.addAll(List.of(args));
        ProcessBuilder builder = ChildJvm.java(command).directory(Files.createDirectories(dir.resolve("cwd")).toFile())
                .redirectOutput(dir.resolve("out").toFile()).redirectError(dir.resolve("err").toFile());
        env.forEach((k, v) -> {
            if (v == null) {
                builder.environment().remove(k);
            } else {
                builder.environment().put(k, v);
            }
        });
        Process p = builder.start();
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).as("the jar exits by itself").isTrue();
        return new Result(p.exitValue(), Files.readString(dir.resolve("out")), Files.readString(dir.resolve("err")));
    }

    private Result java(String... args) throws Exception {
        return java(Map.of(), args);
    }

    private String entry(String name) throws IOException {
        try (ZipFile zip = new ZipFile(jar.toFile())) {
            ZipEntry e = zip.getEntry(name);
            assertThat(e).as(name + " in the jar").isNotNull();
            try (InputStream in = zip.getInputStream(e)) {
                return new String(in.readAllBytes(), StandardCharsets.UTF_8);
            }
        }
    }

    @Test
    void versionPrintsTheBuildsVersion() throws Exception {
        Result r = java("--version");
        assertThat(r.status()).isZero();
        assertThat(r.out().strip()).isEqualTo("gizmoball " + entry("gizmoball/version.txt").strip());
        assertThat(r.err()).isEmpty();
    }

    @Test
    void headlessRunsASampleBoardShippedInsideTheJar() throws Exception {
        String sample = entry("gizmoball/samples/default.txt");
        Path board = Files.writeString(dir.resolve("default.txt"), sample);

        Result r = java("--headless", "--ticks", "60", board.toString());

        assertThat(r.status()).as(r.err()).isZero();
        Board after = BoardFiles.load("stdout", r.out());
        Board before = BoardFiles.load("sample", sample);
        assertThat(after.gizmos()).extracting(Gizmo::name)
                .containsExactlyElementsOf(before.gizmos().stream().map(Gizmo::name).toList());
        assertThat(after.balls()).hasSameSizeAs(before.balls());
    }

    @Test
    void theJarHoldsTheGamePhysicsLibAndEverySampleBoard() throws Exception {
        assertThat(entry("META-INF/MANIFEST.MF")).contains("Main-Class: gizmoball.Main");
        try (ZipFile zip = new ZipFile(jar.toFile())) {
            assertThat(zip.getEntry("physics/Vect.class")).as("physics-lib inside").isNotNull();
        }
        List<String> boards;
        try (Stream<Path> files = Files.list(Path.of("boards"))) {
            boards = files.map(f -> f.getFileName().toString()).sorted().toList();
        }
        assertThat(entry("gizmoball/samples/index.txt").lines().toList()).containsExactlyElementsOf(boards);
        for (String name : boards) {
            assertThat(entry("gizmoball/samples/" + name)).isEqualTo(Files.readString(Path.of("boards", name)));
        }
    }

    @Test
    void withoutADisplayTheWindowModeSaysSoInOneLineWithoutAStackTrace() throws Exception {
        Map<String, String> noDisplay = new HashMap<>();
        noDisplay.put("DISPLAY", null);
        noDisplay.put("WAYLAND_DISPLAY", null);

        for (List<String> args : List.of(List.<String>of(), List.of("board.txt"))) {
            Result r = java(noDisplay, args.toArray(String[]::new));
            assertThat(r.status()).isEqualTo(Main.BAD_USAGE);
            assertThat(r.err()).isEqualTo("gizmoball: no display: set DISPLAY or use --headless"
                    + System.lineSeparator());
            assertThat(r.out()).isEmpty();
        }
    }

    @Test
    void helpAndUnknownOptionsWithoutADisplay() throws Exception {
        Map<String, String> noDisplay = new HashMap<>();
        noDisplay.put("DISPLAY", null);
        Result help = java(noDisplay, "--help");
        assertThat(help.status()).isZero();
        assertThat(help.out()).contains("usage: gizmoball [BOARD]");

        Result bogus = java(noDisplay, "--bogus");
        assertThat(bogus.status()).isEqualTo(Main.BAD_USAGE);
        assertThat(bogus.err()).startsWith("gizmoball: unknown option --bogus").doesNotContain("Exception");
    }
}
