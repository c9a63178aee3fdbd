package gizmoball.controller;

import gizmoball.highscore.HighScoreStore;
import java.awt.Rectangle;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.stream.Collectors;
import java.util.prefs.BackingStoreException;
import java.util.prefs.Preferences;

/**
 * The player's settings that outlive a run: sound, overlay, trails, aim preview, speed, the last folder
 * chosen in the file picker, the boards opened or saved last, and the window's place and size. Stored with java.util.prefs
 * (on Linux under the user's home, never next to the program). A value that is missing or unreadable
 * reads as its default.
 * <p>
 * The game uses the node {@value #DEFAULT_NODE}; the system property {@value #NODE_PROPERTY} names another
 * one, which is how the tests keep their windows off the player's settings.
 */
public final class Settings {
    public static final String NODE_PROPERTY = "gizmoball.prefs.node";
    public static final String DEFAULT_NODE = "/gizmoball";

    private static final String SOUND = "sound";
    private static final String OVERLAY = "physicsOverlay";
    private static final String TRAILS = "ballTrails";
    private static final String AIM_PREVIEW = "aimPreview";
    private static final String SPEED = "speed";
    private static final String LAST_FOLDER = "lastFolder";
    private static final String WINDOW = "window";
    private static final String RECENT = "recentFiles";
    private static final String HINT_SHOWN = "firstRunHintShown";
    /** File > Open recent lists this many boards. */
    public static final int RECENT_FILES = 10;
    private static final String PLAYER = "playerName";
    private static final String HIGH_SCORES = "highscores";

    /** The system property that moves the JDK's file-kept preferences to another folder. */
    public static final String PREFS_ROOT = "java.util.prefs.userRoot";
    private static final String FILE_PREFERENCES = "java.util.prefs.FileSystemPreferences";

    private final Preferences node;

    public Settings(Preferences node) {
        this.node = node;
    }

    /** The settings of this user (or of the node the system property names). */
    public static Settings forUser() {
        return new Settings(Preferences.userRoot().node(System.getProperty(NODE_PROPERTY, DEFAULT_NODE)));
    }

    /**
     * The folder these settings and the high scores are kept in where Java keeps preferences in files (Linux and
     * other Unix): {@code .java/.userPrefs} and the node's path under the folder {@value #PREFS_ROOT} names, else
     * under {@code user.home}, the account's home from the system's user database (so HOME does not move it; that
     * property does). Empty where Java keeps them elsewhere (the Windows registry, a macOS property list).
     */
    public Optional<Path> whereKept() {
        if (!FILE_PREFERENCES.equals(node.getClass().getName())) {
            return Optional.empty();
        }
        String root = System.getProperty(PREFS_ROOT, System.getProperty("user.home"));
        return Optional.of(Path.of(root, ".java", ".userPrefs").resolve(node.absolutePath().substring(1)));
    }

    /** The boards' high-score tables, in a node of their own beside these settings. */
    public HighScoreStore highScores() {
        return new HighScoreStore(node.node(HIGH_SCORES));
    }

    /** The name last given for a high score, else the user's login name. */
    public String playerName() {
        return node.get(PLAYER, System.getProperty("user.name", ""));
    }

    public void setPlayerName(String name) {
        put(PLAYER, name);
    }

    public boolean sound() {
        return node.getBoolean(SOUND, true);
    }

    public void setSound(boolean on) {
        put(SOUND, Boolean.toString(on));
    }

    public boolean physicsOverlay() {
        return node.getBoolean(OVERLAY, false);
    }

    public void setPhysicsOverlay(boolean on) {
        put(OVERLAY, Boolean.toString(on));
    }

    public boolean ballTrails() {
        return node.getBoolean(TRAILS, false);
    }

    public void setBallTrails(boolean on) {
        put(TRAILS, Boolean.toString(on));
    }

    public boolean aimPreview() {
        return node.getBoolean(AIM_PREVIEW, true);
    }

    public void setAimPreview(boolean on) {
        put(AIM_PREVIEW, Boolean.toString(on));
    }

    public Speed speed() {
        String name = node.get(SPEED, Speed.NORMAL.name());
        for (Speed s : Speed.values()) {
            if (s.name().equals(name)) {
                return s;
            }
        }
        return Speed.NORMAL;
    }

    public void setSpeed(Speed speed) {
        put(SPEED, speed.name());
    }

    /** The folder last opened from or saved to, if it still exists. */
    public Optional<Path> lastFolder() {
        String text = node.get(LAST_FOLDER, null);
        if (text == null) {
            return Optional.empty();
        }
        try {
            Path folder = Path.of(text);
            return Files.isDirectory(folder) ? Optional.of(folder) : Optional.empty();
        } catch (InvalidPathException e) {
            return Optional.empty();
        }
    }

    public void setLastFolder(Path folder) {
        put(LAST_FOLDER, folder.toAbsolutePath().normalize().toString());
    }

    /** Whether the first-run hint was shown already (in this run or an earlier one). */
    public boolean firstRunHintShown() {
        return node.getBoolean(HINT_SHOWN, false);
    }

    public void setFirstRunHintShown() {
        put(HINT_SHOWN, "true");
    }

    /** The boards last opened or saved, newest first, at most {@value #RECENT_FILES}; ones gone from disk left out. */
    public List<Path> recentFiles() {
        List<Path> files = new ArrayList<>();
        for (String line : node.get(RECENT, "").split("\n")) {
            try {
                if (!line.isBlank() && Files.isRegularFile(Path.of(line))) {
                    files.add(Path.of(line));
                }
            } catch (InvalidPathException e) {
                // a line no path can be read from: skipped, as a file gone is
            }
        }
        return files;
    }

    /** {@code file} becomes the newest of the recent files (once, however often it is used). */
    public void addRecentFile(Path file) {
        Path absolute = file.toAbsolutePath().normalize();
        List<Path> files = new ArrayList<>(recentFiles());
        files.remove(absolute);
        files.add(0, absolute);
        put(RECENT, files.stream().limit(RECENT_FILES).map(Path::toString).collect(Collectors.joining("\n")));
    }

    /** The window's last place and size on the screen: x, y, width and height, if known. */
    public Optional<Rectangle> windowBounds() {
        String[] parts = node.get(WINDOW, "").split(",");
        if (parts.length != 4) {
            return Optional.empty();
        }
        try {
            int[] v = new int[4];
            for (int i = 0; i < 4; i++) {
                v[i] = Integer.parseInt(parts[i].trim());
            }
            return v[2] > 0 && v[3] > 0 ? Optional.of(new Rectangle(v[0], v[1], v[2], v[3])) : Optional.empty();
        } catch (NumberFormatException e) {
            return Optional.empty();
        }
    }

    public void setWindowBounds(Rectangle r) {
        put(WINDOW, r.x + "," + r.y + "," + r.width + "," + r.height);
    }

    /** Forgets every setting (back to the defaults). */
    public void clear() {
        try {
            node.clear();
            node.flush();
        } catch (BackingStoreException e) {
            // The store is unavailable: there is nothing remembered to forget either.
        }
    }

    /**
     * Written through at once, so a setting survives a crash. A store that cannot be written (read-only
     * home) only means the setting is not remembered: the game goes on.
     */
    private void put(String key, String value) {
        node.put(key, value);
        try {
            node.flush();
        } catch (BackingStoreException e) {
            // Not remembered this time; the value still holds for this run.
        }
    }
}
