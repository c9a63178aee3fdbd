package gizmoball.model;

/** Told about every change of a board: each tick, each successful edit, each wholesale replacement. */
public interface BoardObserver {
    void boardChanged(Board board, BoardChange change);
}
