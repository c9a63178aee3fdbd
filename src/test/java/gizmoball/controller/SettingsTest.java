package gizmoball.controller;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.ChildJvm;
import java.awt.Rectangle;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.prefs.Preferences;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Each test has a private preferences node of its own, removed afterwards: the player's settings are never read or written. */
class SettingsTest {
    private final String path = "/gizmoball-test/" + UUID.randomUUID();
    private final Preferences node = Preferences.userRoot().node(path);

    @AfterEach
    void removeNode() throws Exception {
        node.removeNode();
        node.flush();
    }

    @Test
    void aFreshNodeReadsAsTheDefaults() {
        Settings s = new Settings(node);
        assertThat(s.sound()).isTrue();
        assertThat(s.physicsOverlay()).isFalse();
        assertThat(s.ballTrails()).isFalse();
        assertThat(s.aimPreview()).isTrue();
        assertThat(s.speed()).isEqualTo(Speed.NORMAL);
        assertThat(s.lastFolder()).isEmpty();
        assertThat(s.windowBounds()).isEmpty();
    }

    @Test
    void settingsStickBetweenRuns(@TempDir Path folder) throws Exception {
        Settings s = new Settings(node);
        s.setSound(false);
        s.setPhysicsOverlay(true);
        s.setBallTrails(true);
        s.setAimPreview(false);
        s.setSpeed(Speed.QUARTER);
        s.setLastFolder(folder);
        s.setWindowBounds(new Rectangle(12, 34, 800, 600));

        // Another JVM, as the next run of the game would be, reads them from the store.
        List<String> command = new ArrayList<>(List.of("-cp", location(Settings.class) + File.pathSeparator + location(NextRun.class)));
        String root = System.getProperty("java.util.prefs.userRoot");
        if (root != null) {
            command.add("-Djava.util.prefs.userRoot=" + root);
        }
        command.addAll(List.of(NextRun.class.getName(), path));
        Process p = ChildJvm.java(command).redirectErrorStream(true).start();
        assertThat(p.waitFor(30, TimeUnit.SECONDS)).isTrue();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        assertThat(out).isEqualTo("false true true false QUARTER " + folder.toAbsolutePath().normalize()
                + " java.awt.Rectangle[x=12,y=34,width=800,height=600]");
    }

    /**
     * Issue 40 item 13: where the settings are kept is where the JDK writes them: the folder the preferences root
     * property names (the tests set it), then .java/.userPrefs and the node's path.
     */
    @Test
    void theySayTheFolderTheyAreWrittenTo() throws Exception {
        Settings s = new Settings(node);
        s.setSpeed(Speed.HALF);
        node.flush();
        Path folder = Path.of(System.getProperty(Settings.PREFS_ROOT), ".java", ".userPrefs", path.substring(1));
        assertThat(s.whereKept()).contains(folder);
        assertThat(folder.resolve("prefs.xml")).exists();
    }

    @Test
    void unreadableValuesReadAsTheDefaults(@TempDir Path folder) {
        node.put("speed", "WARP");
        node.put("window", "1,2,three,4");
        node.put("sound", "loud");
        node.put("lastFolder", folder.resolve("gone").toString());
        Settings s = new Settings(node);
        assertThat(s.speed()).isEqualTo(Speed.NORMAL);
        assertThat(s.windowBounds()).isEmpty();
        assertThat(s.sound()).isTrue();
        assertThat(s.lastFolder()).as("a folder that no longer exists").isEmpty();
        node.put("window", "1,2,0,4");
        assertThat(s.windowBounds()).as("no width").isEmpty();
    }

    @Test
    void clearForgetsEverything(@TempDir Path folder) {
        Settings s = new Settings(node);
        s.setSpeed(Speed.DOUBLE);
        s.setLastFolder(folder);
        s.clear();
        assertThat(s.speed()).isEqualTo(Speed.NORMAL);
        assertThat(s.lastFolder()).isEmpty();
    }

    /** The classes folder or jar {@code type} was loaded from (the test launcher's class path may not list it). */
    private static String location(Class<?> type) throws Exception {
        return Path.of(type.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
    }

    /** The next run: prints the settings stored under the node named by its argument. */
    public static final class NextRun {
        public static void main(String[] args) {
            Settings s = new Settings(Preferences.userRoot().node(args[0]));
            System.out.println(s.sound() + " " + s.physicsOverlay() + " " + s.ballTrails() + " " + s.aimPreview() + " "
                    + s.speed() + " " + s.lastFolder().map(Path::toString).orElse("-") + " "
                    + s.windowBounds().map(Rectangle::toString).orElse("-"));
        }
    }

    /** Issue 23: File > Open recent's list: newest first, once each, at most ten, files gone left out. */
    @Test
    void recentFilesAreTheLastTenNewestFirstEachOnceAndOnlyThoseStillThere(@TempDir Path dir) throws Exception {
        Settings s = new Settings(node);
        List<Path> files = new ArrayList<>();
        for (int i = 0; i < 12; i++) {
            files.add(java.nio.file.Files.writeString(dir.resolve("b" + i + ".txt"), "Gravity 25.0\n"));
            s.addRecentFile(files.get(i));
        }
        s.addRecentFile(files.get(5));
        java.nio.file.Files.delete(files.get(11));

        assertThat(s.recentFiles()).containsExactly(files.get(5), files.get(10), files.get(9), files.get(8),
                files.get(7), files.get(6), files.get(4), files.get(3), files.get(2));
        assertThat(new Settings(node).recentFiles()).as("remembered").hasSize(9);
    }
}
