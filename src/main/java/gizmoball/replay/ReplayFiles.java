package gizmoball.replay;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.JsonParseException;
import gizmoball.boardfile.AtomicFileWriter;
import gizmoball.boardfile.FileErrors;
import gizmoball.model.game.KeyPress;
import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Replay files: JSON, {@code {"format": "gizmoball replay", "version": 1, "board": "...", "dt": ..., "ticks": ...,
 * "score": ..., "players": ..., "keys": [{"tick": 12, "key": "down", "code": 32}, ...]}}. The board is the board-file
 * text as built; doubles are written so that they read back to the same bits. A file without "players" (written before
 * games had several) is of one player.
 */
public final class ReplayFiles {
    static final String FORMAT = "gizmoball replay";
    static final int VERSION = 1;
    private static final Gson GSON = new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create();

    private ReplayFiles() {
    }

    /** Not a replay this version reads; the message names the source and says why. */
    public static final class BadReplay extends Exception {
        private static final long serialVersionUID = 1L;

        BadReplay(String message) {
            super(message);
        }
    }

    /** The file's layout, as Gson reads and writes it. */
    private static final class Json {
        String format;
        Integer version;
        String board;
        Double dt;
        Long ticks;
        Long score;
        Integer players;
        List<Key> keys;
    }

    private static final class Key {
        Long tick;
        String key;
        Integer code;
    }

    public static String toJson(Replay replay) {
        Json json = new Json();
        json.format = FORMAT;
        json.version = VERSION;
        json.dt = replay.dt();
        json.ticks = replay.ticks();
        json.score = replay.score();
        json.players = replay.players();
        json.keys = new ArrayList<>();
        for (KeyPress press : replay.keys().keys()) {
            Key key = new Key();
            key.tick = press.tick();
            key.key = press.motion().name().toLowerCase(Locale.ROOT);
            key.code = press.keyCode();
            json.keys.add(key);
        }
        json.board = replay.board();
        return GSON.toJson(json) + "\n";
    }

    /** @param source names the replay in messages */
    public static Replay fromJson(String source, String text) throws BadReplay {
        Json json;
        try {
            json = GSON.fromJson(text, Json.class);
        } catch (JsonParseException e) {
            throw new BadReplay(source + " is not a replay file: a replay is JSON text, and this is not");
        }
        if (json == null || !FORMAT.equals(json.format)) {
            throw new BadReplay(source + " is not a replay file: it does not say \"format\": \"" + FORMAT + "\"");
        }
        if (json.version == null || json.version != VERSION) {
            throw new BadReplay(source + ": a replay of version " + json.version + "; this game reads version "
                    + VERSION);
        }
        require(source, "board", "the board it was played on", json.board);
        require(source, "dt", "the length of a tick", json.dt);
        require(source, "ticks", "how many ticks it lasts", json.ticks);
        require(source, "score", "the score it reached", json.score);
        require(source, "keys", "the keys pressed", json.keys);
        List<KeyPress> keys = new ArrayList<>();
        for (int i = 0; i < json.keys.size(); i++) {
            Key key = json.keys.get(i);
            if (key == null || key.tick == null || key.code == null
                    || !("down".equals(key.key) || "up".equals(key.key))) {
                throw new BadReplay(source + ": key " + (i + 1) + " needs a tick, \"key\": \"down\" or \"up\", and a"
                        + " code");
            }
            try {
                keys.add(new KeyPress(key.tick, "down".equals(key.key) ? KeyPress.Motion.DOWN : KeyPress.Motion.UP,
                        key.code));
            } catch (IllegalArgumentException e) {
                throw new BadReplay(source + ": key " + (i + 1) + ": " + e.getMessage());
            }
        }
        try {
            return new Replay(json.board, json.dt, json.ticks, new KeyScript(keys), json.score,
                    json.players == null ? 1 : json.players);
        } catch (IllegalArgumentException e) {
            throw new BadReplay(source + ": " + e.getMessage());
        }
    }

    private static void require(String source, String field, String meaning, Object value) throws BadReplay {
        if (value == null) {
            throw new BadReplay(source + " is not a whole replay: it has no \"" + field + "\" (" + meaning + ")");
        }
    }

    public static Replay read(Path file) throws IOException, BadReplay {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (CharacterCodingException e) {
            throw new BadReplay(file + " is not a replay file: " + FileErrors.readReason(file, e));
        }
        return fromJson(file.toString(), text);
    }

    /** All at once: a failed write leaves an earlier file as it was. */
    public static void write(Replay replay, Path file) throws IOException {
        String json = toJson(replay);
        AtomicFileWriter.write(file, out -> out.write(json));
    }
}
