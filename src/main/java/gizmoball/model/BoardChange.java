package gizmoball.model;

/** What kind of change an observer is told about. */
public enum BoardChange {
    /** Stage 6 of a tick. */
    TICK,
    /** After a successful editing operation. */
    EDIT,
    /** After {@link Board#replaceContents(Board)} or {@link Board#clear()}. */
    REPLACE
}
