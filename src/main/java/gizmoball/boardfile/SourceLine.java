package gizmoball.boardfile;

/** One line of a board file as written: its 1-based number and its text without the line terminator. */
public record SourceLine(int number, String text) {
}
