package gizmoball.controller.editor;

import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.GizmoKind;
import org.junit.jupiter.api.Test;

import java.util.concurrent.atomic.AtomicInteger;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

class EditHistoryTest {
    private final Board board = new Board();
    private final EditHistory history = new EditHistory(board);

    @Test
    void aCompoundEditRefusedHalfWayIsRolledBackCompletely() {
        assertThatThrownBy(() -> history.perform(b -> {
            b.addGizmo(GizmoKind.SQUARE, "S1", 0, 0);
            b.addGizmo(GizmoKind.SQUARE, "S2", 0, 0);
        })).isInstanceOf(BoardEditException.class);

        assertThat(board.gizmos()).isEmpty();
        assertThat(history.canUndo()).isFalse();
    }

    @Test
    void undoAndRedoRestoreWholeSnapshots() {
        history.perform(b -> b.addGizmo(GizmoKind.SQUARE, "S1", 0, 0));
        history.perform(b -> {
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
    void onlyReplacementsFromElsewhereAreReportedAsForeign() {
        AtomicInteger foreign = new AtomicInteger();
        history.addForeignReplaceListener(foreign::incrementAndGet);
        history.perform(b -> b.addGizmo(GizmoKind.CIRCLE, "C1", 1, 1));
        history.undo();
        history.redo();
        assertThat(foreign).hasValue(0);

        board.replaceContents(new Board());
        assertThat(foreign).hasValue(1);
    }

    @Test
    void theOldestStepsAreForgottenBeyondTheLimit() {
        for (int i = 0; i < EditHistory.LIMIT + 5; i++) {
            double g = i;
            history.perform(b -> b.setGravity(g));
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
