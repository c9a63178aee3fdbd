package gizmoball.model;

import java.util.Arrays;
import java.util.Objects;

/**
 * The observers of a board. Copy on write, so that an observer may add or remove observers while it is told of a
 * change: telling walks the array as it was when the change began, and makes nothing (a board tells at every tick).
 */
final class Observers {
    private volatile BoardObserver[] observers = new BoardObserver[0];

    synchronized void add(BoardObserver observer) {
        BoardObserver[] more = Arrays.copyOf(observers, observers.length + 1);
        more[observers.length] = observer;
        observers = more;
    }

    /** Removes the first registration of the observer, as {@code List.remove} would. */
    synchronized void remove(BoardObserver observer) {
        BoardObserver[] now = observers;
        for (int i = 0; i < now.length; i++) {
            if (Objects.equals(now[i], observer)) {
                BoardObserver[] fewer = new BoardObserver[now.length - 1];
                System.arraycopy(now, 0, fewer, 0, i);
                System.arraycopy(now, i + 1, fewer, i, now.length - i - 1);
                observers = fewer;
                return;
            }
        }
    }

    void tell(Board board, BoardChange change) {
        for (BoardObserver observer : observers) {
            observer.boardChanged(board, change);
        }
    }
}
