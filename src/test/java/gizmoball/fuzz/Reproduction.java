package gizmoball.fuzz;

import gizmoball.boardfile.BoardFileException;
import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;

import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A board file that reproduces a run: its first line says how many ticks to play, its {@code # key} comment lines
 * are the {@link KeyScript}, the rest is an ordinary board (the form of {@code ../shared/repro/}).
 */
public record Reproduction(String boardText, int ticks, KeyScript keys) {
    /** Every tick of a reproduction is 1/60 s. */
    public static final double DT = Board.DEFAULT_TICK;

    private static final Pattern HEADER = Pattern.compile("#\\s*reproduction: play (\\d+) ticks.*");

    /** Reads a reproduction's text; {@code source} names it in errors. */
    public static Reproduction parse(String source, String text) {
        String first = text.lines().findFirst().orElse("").strip();
        Matcher m = HEADER.matcher(first);
        if (!m.matches()) {
            throw new IllegalArgumentException(source + ":1: expected '# reproduction: play N ticks ...', found: " + first);
        }
        return new Reproduction(text, Integer.parseInt(m.group(1)), KeyScript.fromComments(text));
    }

    /** A board in its canonical form with how long to play it and its keys. */
    public static Reproduction of(Board board, int ticks, KeyScript keys) {
        return new Reproduction(BoardFiles.toText(board), ticks, keys);
    }

    /** A new board as the file describes it, before any tick. */
    public Board load(String source) throws BoardFileException {
        return BoardFiles.load(source, boardText);
    }

    /** The file's text: the header, the board, the key lines (a board already carrying key lines keeps only those). */
    public String toText() {
        String header = String.format(Locale.ROOT, "# reproduction: play %d ticks at 1/60 s; \"# key T CODE down|up\" "
                + "presses or releases CODE before tick T (ticks counted from 1)\n", ticks);
        String body = boardText.lines().filter(l -> !HEADER.matcher(l.strip()).matches()).map(l -> l + "\n")
                .reduce("", String::concat);
        boolean keysInBody = !KeyScript.fromComments(body).presses().isEmpty();
        return header + body + (keysInBody ? "" : keys.toComments());
    }
}
