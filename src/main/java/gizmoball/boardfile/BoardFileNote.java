package gizmoball.boardfile;

/**
 * How one line of a board file was understood where it was not written in the canonical form (another
 * implementation's spelling, a renamed ball, balls placed on each other, a reference to a later line). A note
 * never stops a load.
 *
 * @param source the file (or other source) name, as given by the caller
 * @param line   1-based line number
 * @param text   the line, without its terminator
 * @param note   what was understood
 */
public record BoardFileNote(String source, int line, String text, String note) {

    static BoardFileNote at(String source, SourceLine line, String note) {
        return new BoardFileNote(source, line.number(), line.text(), note);
    }

    /** {@code file:line: note: text}, the shape of {@link BoardFileError}. */
    @Override
    public String toString() {
        return source + ":" + line + ": " + note + ": " + text.strip();
    }
}
