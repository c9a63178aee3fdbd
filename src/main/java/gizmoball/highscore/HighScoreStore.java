package gizmoball.highscore;

import com.google.gson.Gson;
import com.google.gson.JsonParseException;
import gizmoball.replay.Replay;
import gizmoball.replay.ReplayFiles;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.LocalDate;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.Base64;
import java.util.HexFormat;
import java.util.List;
import java.util.Optional;
import java.util.prefs.BackingStoreException;
import java.util.prefs.Preferences;
import java.util.zip.GZIPInputStream;
import java.util.zip.GZIPOutputStream;

/**
 * The players' high-score tables, one per board content as built (the SHA-256 of its canonical board-file text, so
 * an edited board starts a new table), in a java.util.prefs node of their own beside the settings. A table is JSON
 * with each entry's replay, gzipped and in Base64, split over values of at most {@link Preferences#MAX_VALUE_LENGTH}.
 * A table that cannot be read is reported and read as empty: the next entry starts it afresh.
 */
public final class HighScoreStore {
    private static final String PARTS = "parts";
    private static final String PART = "part";
    private static final int KEY_HEX_DIGITS = 40;
    private static final Gson GSON = new Gson();

    private final Preferences tables;

    /** @param tables the node whose children are the boards' tables */
    public HighScoreStore(Preferences tables) {
        this.tables = tables;
    }

    /** A table as read: what it holds, and why it could not be read if it could not. */
    public record Loaded(HighScoreTable table, Optional<String> problem) {
    }

    private static final class Json {
        List<Entry> entries;
    }

    private static final class Entry {
        String name;
        Long score;
        String date;
        String replay;
    }

    /** The table of the board whose canonical text as built is {@code board}; empty if it has none yet. */
    public Loaded load(String board) {
        try {
            Preferences node = nodeOf(board);
            if (node == null) {
                return new Loaded(HighScoreTable.EMPTY, Optional.empty());
            }
            return new Loaded(decode(board, node), Optional.empty());
        } catch (BackingStoreException | IOException | RuntimeException | ReplayFiles.BadReplay e) {
            return new Loaded(HighScoreTable.EMPTY, Optional.of("The high scores of this board could not be read ("
                    + e.getMessage() + "); the next high score starts them afresh."));
        }
    }

    /** Replaces the board's table; the message of a store that refuses it. */
    public Optional<String> save(String board, HighScoreTable table) {
        try {
            Preferences node = tables.node(keyOf(board));
            node.clear();
            String data = encode(table);
            int parts = (data.length() + Preferences.MAX_VALUE_LENGTH - 1) / Preferences.MAX_VALUE_LENGTH;
            for (int i = 0; i < parts; i++) {
                node.put(PART + i, data.substring(i * Preferences.MAX_VALUE_LENGTH,
                        Math.min(data.length(), (i + 1) * Preferences.MAX_VALUE_LENGTH)));
            }
            node.putInt(PARTS, parts);
            node.flush();
            return Optional.empty();
        } catch (BackingStoreException | IOException | RuntimeException e) {
            return Optional.of("The high score could not be kept: " + e.getMessage());
        }
    }

    private Preferences nodeOf(String board) throws BackingStoreException {
        String key = keyOf(board);
        return tables.nodeExists(key) ? tables.node(key) : null;
    }

    /** The first 40 hex digits of the SHA-256 of the text: a prefs node name (at most 80 characters). */
    static String keyOf(String board) {
        try {
            byte[] digest = MessageDigest.getInstance("SHA-256").digest(board.getBytes(StandardCharsets.UTF_8));
            return HexFormat.of().formatHex(digest).substring(0, KEY_HEX_DIGITS);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }

    private static String encode(HighScoreTable table) throws IOException {
        Json json = new Json();
        json.entries = new ArrayList<>();
        for (HighScore score : table.entries()) {
            Entry entry = new Entry();
            entry.name = score.name();
            entry.score = score.score();
            entry.date = score.date().toString();
            entry.replay = ReplayFiles.toJson(score.replay());
            json.entries.add(entry);
        }
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (GZIPOutputStream zip = new GZIPOutputStream(bytes)) {
            zip.write(GSON.toJson(json).getBytes(StandardCharsets.UTF_8));
        }
        return Base64.getEncoder().encodeToString(bytes.toByteArray());
    }

    private static HighScoreTable decode(String board, Preferences node) throws IOException, ReplayFiles.BadReplay {
        int parts = node.getInt(PARTS, -1);
        if (parts < 1) {
            throw new IOException("no parts recorded");
        }
        StringBuilder data = new StringBuilder();
        for (int i = 0; i < parts; i++) {
            String part = node.get(PART + i, null);
            if (part == null) {
                throw new IOException("part " + i + " of " + parts + " is missing");
            }
            data.append(part);
        }
        byte[] zipped;
        try {
            zipped = Base64.getDecoder().decode(data.toString());
        } catch (IllegalArgumentException e) {
            throw new IOException("not Base64: " + e.getMessage(), e);
        }
        String text;
        try (GZIPInputStream in = new GZIPInputStream(new ByteArrayInputStream(zipped))) {
            text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        Json json;
        try {
            json = GSON.fromJson(text, Json.class);
        } catch (JsonParseException e) {
            throw new IOException("not a table: " + e.getMessage(), e);
        }
        if (json == null || json.entries == null) {
            throw new IOException("not a table");
        }
        List<HighScore> entries = new ArrayList<>();
        for (Entry entry : json.entries) {
            if (entry == null || entry.name == null || entry.score == null || entry.date == null || entry.replay == null) {
                throw new IOException("an entry lacks its name, score, date or replay");
            }
            Replay replay = ReplayFiles.fromJson("the replay of " + entry.name, entry.replay);
            if (!replay.board().equals(board)) {
                throw new IOException("the replay of " + entry.name + " is of another board");
            }
            try {
                entries.add(new HighScore(entry.name, entry.score, LocalDate.parse(entry.date), replay));
            } catch (DateTimeParseException e) {
                throw new IOException("the date of " + entry.name + " is no date: " + entry.date, e);
            }
        }
        return new HighScoreTable(entries);
    }
}
