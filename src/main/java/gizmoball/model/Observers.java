package gizmoball.model;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * The observers of a board. Copy on write, so that an observer may add or remove observers while it is told of a
 * change.
 */
final class Observers {
    private final List<BoardObserver> observers = new CopyOnWriteArrayList<>();

    void add(BoardObserver observer) {
        observers.add(observer);
    }

    void remove(BoardObserver observer) {
        observers.remove(observer);
    }

    void tell(Board board, BoardChange change) {
        for (BoardObserver observer : observers) {
            observer.boardChanged(board, change);
        }
    }
}
