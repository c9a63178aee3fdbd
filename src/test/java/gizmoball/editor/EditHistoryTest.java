package gizmoball.editor;

import gizmoball.boardfile.BoardContents;
import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.gizmo.GizmoKind;
import org.junit.jupiter.api.Test;

import java.util.concurrent.atomic.AtomicInteger;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

class EditHistoryTest {
    private final Board board = new Board();
    private final EditHistory history = new EditHistory(board);

    @Test
    void aCompoundEditRefusedHalfWayIsRolledBackCompletely() {
        assertThatThrownBy(() -> history.perform("edit", b -> {
            b.addGizmo(GizmoKind.SQUARE, "S1", 0, 0);
            b.addGizmo(GizmoKind.SQUARE, "S2", 0, 0);
        })).isInstanceOf(BoardEditException.class);

        assertThat(board.gizmos()).isEmpty();
        assertThat(history.canUndo()).isFalse();
    }

    @Test
    void undoAndRedoRestoreWholeSnapshots() {
        history.perform("edit", b -> b.addGizmo(GizmoKind.SQUARE, "S1", 0, 0));
        history.perform("edit", b -> {
            b.addBall("B1", 5, 5, 1, 1);
            b.setGravity(3);
        });
        BoardContents after = BoardContents.of(board);

        history.undo();
        assertThat(board.balls()).isEmpty();
        assertThat(board.gravity()).isEqualTo(Board.DEFAULT_GRAVITY);
        assertThat(board.gizmos()).hasSize(1);
        history.redo();
        assertThat(BoardContents.of(board)).isEqualTo(after);
    }

    @Test
    void anotherDesignReplacingTheBoardStartsAFreshHistory() {
        AtomicInteger resets = new AtomicInteger();
        history.addResetListener(resets::incrementAndGet);
        history.perform("edit", b -> b.addGizmo(GizmoKind.CIRCLE, "C1", 1, 1));
        history.undo();
        history.redo();
        assertThat(resets).hasValue(0);

        board.replaceContents(new Board());
        assertThat(resets).hasValue(1);
        assertThat(history.canUndo()).isFalse();
        assertThat(history.canRedo()).isFalse();
    }

    @Test
    void theSameDesignComingBackFromPlayKeepsTheHistory() {
        history.perform("edit", b -> b.addBall("B1", 5, 5, 3, 0));
        Board design = board.copy();
        board.tick(0.25);
        assertThat(board.ball("B1").orElseThrow().position().x()).isGreaterThan(5.5);

        board.replaceContents(design);
        assertThat(history.canUndo()).isTrue();
        history.undo();
        assertThat(board.balls()).isEmpty();
    }

    @Test
    void anEditMadeElsewhereBecomesAnUndoStep() {
        history.perform("Placed S1", b -> b.addGizmo(GizmoKind.SQUARE, "S1", 1, 1));
        board.addGizmo(GizmoKind.SQUARE, "S2", 3, 3);
        assertThat(history.undoable()).contains(EditHistory.ELSEWHERE);

        history.undo();
        assertThat(board.gizmos()).extracting(g -> g.name()).containsExactly("S1");
        assertThat(history.undoable()).contains("Placed S1");
        assertThat(history.redoable()).contains(EditHistory.ELSEWHERE);
        history.undo();
        assertThat(board.gizmos()).isEmpty();
    }

    @Test
    void theOldestStepsAreForgottenBeyondTheLimit() {
        for (int i = 0; i < EditHistory.LIMIT + 5; i++) {
            double g = i;
            history.perform("edit", b -> b.setGravity(g));
        }
        int undone = 0;
        while (history.undo()) {
            undone++;
        }
        assertThat(undone).isEqualTo(EditHistory.LIMIT);
        // The oldest 5 steps are gone: the board stops at the state after step 5 (gravity 4).
        assertThat(board.gravity()).isEqualTo(4);
    }
}
