package gizmoball.boardfile;

/**
 * Why one line of a board file was refused.
 *
 * @param source the file (or other source) name, as given by the caller
 * @param line   1-based line number
 * @param text   the offending line, without its terminator
 * @param reason what is wrong with it
 */
public record BoardFileError(String source, int line, String text, String reason) {

    static BoardFileError at(String source, SourceLine line, String reason) {
        return new BoardFileError(source, line.number(), line.text(), reason);
    }

    /** {@code file:line: reason: text}, the shape compilers use, so editors can jump to it. */
    @Override
    public String toString() {
        return source + ":" + line + ": " + reason + ": " + text.strip();
    }
}
