package gizmoball.editor;

import gizmoball.boardfile.BoardContents;
import gizmoball.model.Board;
import gizmoball.model.BoardChange;
import gizmoball.model.BoardObserver;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * Undo and redo for build mode, by whole-board snapshots: before each edit the board is copied; undo puts the
 * copy back with {@link Board#replaceContents}. Snapshots cannot drift from the model the way hand-written
 * inverse operations could, and boards are small (a few hundred objects at most).
 * <p>
 * An edit made of several board operations is atomic: if a later operation is refused, the earlier ones are
 * rolled back from the snapshot, so nothing is ever half-applied.
 * <p>
 * Changes made by others are noticed too: an edit from elsewhere becomes an undo step of its own; a replacement
 * of the whole contents by a different design (Open, New) starts a fresh history, because steps recorded against
 * the old board would undo into it. Replacements that bring back the same design (returning from play) keep it.
 */
public final class EditHistory {
    /** Enough for any editing session; bounds the memory a long session can hold. */
    static final int LIMIT = 200;

    private final Board board;
    /** A board as it was, and what the edit that left it did (for "Undo Placed S1" in menus and messages). */
    private record Step(Board board, String what) { }

    static final String ELSEWHERE = "change made outside the editor";

    private final Deque<Step> undo = new ArrayDeque<>();
    private final Deque<Step> redo = new ArrayDeque<>();
    private final List<Runnable> listeners = new ArrayList<>();
    private final List<Runnable> resetListeners = new ArrayList<>();
    /** The board as this history last saw it, to recognise what a change from elsewhere did. */
    private Board current;
    private boolean ownChange;
    private int editsDuringOperation;

    public EditHistory(Board board) {
        this.board = board;
        this.current = board.copy();
        board.addObserver(new BoardObserver() {
            @Override
            public void boardChanged(Board b, BoardChange change) {
                if (ownChange) {
                    editsDuringOperation++;
                } else if (change != BoardChange.TICK) {
                    changedElsewhere(change);
                }
            }
        });
    }

    /**
     * Runs the edit on the board; {@code what} says what it does ("Placed S1 at (3,4)"). On success the board as it was before becomes an undo step and the redo
     * stack is dropped; on a refusal the board is left exactly as before and the exception is rethrown.
     */
    public void perform(String what, Consumer<Board> edit) {
        Board before = board.copy();
        ownChange = true;
        editsDuringOperation = 0;
        try {
            edit.accept(board);
        } catch (RuntimeException refused) {
            if (editsDuringOperation > 0) {
                board.replaceContents(before);
            }
            throw refused;
        } finally {
            ownChange = false;
        }
        record(new Step(before, what));
    }

    public boolean canUndo() {
        return !undo.isEmpty();
    }

    public boolean canRedo() {
        return !redo.isEmpty();
    }

    /** What Undo would take back, if anything. */
    public Optional<String> undoable() {
        return Optional.ofNullable(undo.peek()).map(Step::what);
    }

    /** What Redo would do again, if anything. */
    public Optional<String> redoable() {
        return Optional.ofNullable(redo.peek()).map(Step::what);
    }

    /** Puts back the board as it was before the last edit; false if there is nothing to undo. */
    public boolean undo() {
        return swap(undo, redo);
    }

    /** Re-applies the last undone edit; false if there is nothing to redo. */
    public boolean redo() {
        return swap(redo, undo);
    }

    /** Called after every change of what can be undone or redone (to enable menu items). */
    public void addListener(Runnable listener) {
        listeners.add(listener);
    }

    /** Called when another design replaced the board and the history started afresh. */
    public void addResetListener(Runnable listener) {
        resetListeners.add(listener);
    }

    private void changedElsewhere(BoardChange change) {
        if (BoardContents.of(board).equals(BoardContents.of(current))) {
            return;
        }
        if (change == BoardChange.EDIT) {
            record(new Step(current, ELSEWHERE));
            return;
        }
        undo.clear();
        redo.clear();
        current = board.copy();
        resetListeners.forEach(Runnable::run);
        fire();
    }

    private void record(Step step) {
        undo.push(step);
        while (undo.size() > LIMIT) {
            undo.removeLast();
        }
        redo.clear();
        current = board.copy();
        fire();
    }

    private boolean swap(Deque<Step> from, Deque<Step> to) {
        if (from.isEmpty()) {
            return false;
        }
        Step step = from.pop();
        to.push(new Step(board.copy(), step.what()));
        ownChange = true;
        try {
            board.replaceContents(step.board());
        } finally {
            ownChange = false;
        }
        current = board.copy();
        fire();
        return true;
    }

    private void fire() {
        listeners.forEach(Runnable::run);
    }
}
