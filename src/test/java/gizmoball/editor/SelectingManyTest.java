package gizmoball.editor;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardContents;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;
import java.awt.event.KeyEvent;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import physics.Vect;

/**
 * Issue 23, selecting many: a rubber band and Shift+click select; the group moves (drag, arrow keys), turns, is
 * deleted, copied, cut, pasted and duplicated, each one undo step.
 */
class SelectingManyTest extends EditorFixture {
    @BeforeEach
    void setUp() {
        board.addGizmo(GizmoKind.SQUARE, "S1", 2, 2);
        board.addGizmo(GizmoKind.SQUARE, "S2", 3, 2);
        board.addGizmo(GizmoKind.TRIANGLE, "T1", 4, 2);
        board.addGizmo(GizmoKind.CIRCLE, "C1", 10, 10);
        board.addBall("B1", 3.5, 4.5, 2, 0);
        board.connect(TriggerSource.gizmo("S1"), "T1");
        board.connect(TriggerSource.gizmo("S1"), "C1");
        board.bindKey(KeyEvent.VK_SPACE, KeyEdge.DOWN, "T1");
        editor.setTool(Tool.SELECT);
    }

    private void drag(double x0, double y0, double x1, double y1, boolean shift) {
        editor.press(x0, y0, shift);
        editor.drag((x0 + x1) / 2, (y0 + y1) / 2);
        editor.drag(x1, y1);
        editor.release(x1, y1);
    }

    private void band(double x0, double y0, double x1, double y1) {
        drag(x0, y0, x1, y1, false);
    }

    @Test
    void aRubberBandSelectsTheGizmosItTouchesAndTheBallsWhoseCentresItHolds() {
        band(1.5, 1.5, 3.6, 5);
        assertThat(editor.selection()).containsExactly("S1", "S2", "B1");
        assertThat(editor.selected()).as("the panels show the last").contains("B1");
        assertThat(lastMessage()).isEqualTo("Selected S1, S2 and B1");

        band(1.5, 1.5, 3.2, 2.5);
        assertThat(editor.selection()).as("a new band replaces the selection").containsExactly("S1", "S2");
        drag(9.5, 9.5, 11, 11, true);
        assertThat(editor.selection()).as("Shift adds").containsExactly("S1", "S2", "C1");
    }

    @Test
    void whileTheBandIsDraggedTheStepHoldsItsCornersAndABandThatHardlyMovedIsAClick() {
        editor.press(1, 1);
        editor.drag(6, 3);
        assertThat(editor.step()).isEqualTo(new PendingStep.Banding(1, 1, 6, 3, false));
        editor.release(6, 3);
        assertThat(editor.step()).isEqualTo(PendingStep.NONE);

        editor.press(8, 8);
        editor.release(8.02, 8);
        assertThat(editor.selection()).as("a click on an empty cell selects nothing").isEmpty();
        editor.press(-0.5, 8);
        editor.release(-0.5, 8);
        assertThat(editor.wallsSelected()).as("outside the board: the walls").isTrue();
    }

    @Test
    void shiftClickAddsAndTakesOut() {
        editor.press(2.5, 2.5);
        editor.release(2.5, 2.5);
        editor.press(10.5, 10.5, true);
        editor.release(10.5, 10.5);
        editor.press(3.5, 4.5, true);
        assertThat(editor.selection()).containsExactly("S1", "C1", "B1");
        editor.press(10.5, 10.5, true);
        assertThat(editor.selection()).containsExactly("S1", "B1");
        assertThat(editor.step()).as("Shift+click starts no drag").isEqualTo(PendingStep.NONE);
        editor.press(12.5, 12.5);
        editor.release(12.5, 12.5);
        assertThat(editor.selection()).as("a plain click elsewhere selects nothing").isEmpty();
    }

    @Test
    void draggingOneOfTheGroupMovesTheGroupAsOneUndoStep() {
        band(1.5, 1.5, 4.5, 4.7);
        assertThat(editor.selection()).containsExactly("S1", "S2", "T1", "B1");
        editor.press(2.5, 2.5);
        editor.drag(4.5, 3.5);
        Preview.Group preview = (Preview.Group) editor.preview().orElseThrow();
        assertThat(preview.fits()).isTrue();
        assertThat(preview.parts()).hasSize(4).first()
                .isEqualTo(new Preview.Footprint(4, 3, 1, 1, java.util.Optional.empty()));
        editor.release(4.5, 3.5);

        assertThat(List.of(gizmo("S1").x(), gizmo("S2").x(), gizmo("T1").x(), gizmo("T1").y()))
                .containsExactly(4, 5, 6, 3);
        assertThat(board.ball("B1").orElseThrow().position()).isEqualTo(new Vect(5.5, 5.5));
        assertThat(editor.selection()).containsExactly("S1", "S2", "T1", "B1");
        assertThat(editor.history().undoable()).contains("Moved S1, S2, T1 and B1 by (2,1)");
        editor.undo();
        assertThat(gizmo("S1").x()).isEqualTo(2);
        assertThat(board.ball("B1").orElseThrow().position()).isEqualTo(new Vect(3.5, 4.5));
    }

    @Test
    void aGroupDraggedOntoAGizmoIsRefusedWithTheReasonAndMovesNothing() {
        band(1.5, 1.5, 4.5, 2.5);
        String before = BoardContents.of(board).toString();
        var undoable = editor.history().undoable();
        editor.press(2.5, 2.5);
        editor.drag(8.5, 10.5);
        Preview preview = editor.preview().orElseThrow();
        assertThat(preview.problem()).hasValueSatisfying(p -> assertThat(p).contains("would overlap gizmo C1"));
        assertThat(lastMessage()).contains("would overlap gizmo C1");
        editor.release(8.5, 10.5);
        assertThat(BoardContents.of(board).toString()).isEqualTo(before);
        assertThat(editor.history().undoable()).isEqualTo(undoable);
    }

    @Test
    void arrowKeysMoveTheGroupAlongItselfAndABallOnlyGroupByQuarterCells() {
        band(1.5, 1.5, 4.5, 2.5);
        editor.keyPressed(KeyEvent.VK_RIGHT, false);
        assertThat(List.of(gizmo("S1").x(), gizmo("S2").x(), gizmo("T1").x())).containsExactly(3, 4, 5);
        editor.keyPressed(KeyEvent.VK_LEFT, false);
        editor.keyPressed(KeyEvent.VK_LEFT, false);
        assertThat(List.of(gizmo("S1").x(), gizmo("S2").x(), gizmo("T1").x())).containsExactly(1, 2, 3);
        editor.undo();
        editor.undo();
        assertThat(gizmo("S1").x()).as("each key one undo step").isEqualTo(3);

        board.addBall("B2", 6.5, 6.5, 0, 0);
        editor.selectAll(List.of("B1", "B2"), false);
        editor.keyPressed(KeyEvent.VK_DOWN, false);
        assertThat(board.ball("B1").orElseThrow().position()).isEqualTo(new Vect(3.5, 4.75));
        assertThat(board.ball("B2").orElseThrow().position()).isEqualTo(new Vect(6.5, 6.75));
    }

    @Test
    void rotateTurnsEachThatTurnsAndDeleteTakesAllInOneStep() {
        band(1.5, 1.5, 11, 11);
        assertThat(editor.selection()).containsExactly("S1", "S2", "T1", "C1", "B1");
        assertThat(editor.rotateSelected()).isTrue();
        assertThat(List.of(gizmo("S1").rotation(), gizmo("T1").rotation(), gizmo("C1").rotation()))
                .containsExactly(1, 1, 0);
        assertThat(editor.history().undoable()).contains("Rotated S1, S2 and T1");

        assertThat(editor.deleteSelected()).isTrue();
        assertThat(board.gizmos()).isEmpty();
        assertThat(board.balls()).isEmpty();
        assertThat(editor.selection()).isEmpty();
        assertThat(editor.history().undoable()).contains("Deleted S1, S2, T1 and 2 more");
        editor.undo();
        assertThat(board.gizmos()).hasSize(4);
        assertThat(board.connections()).hasSize(2);
    }

    @Test
    void onlyCirclesSelectedAreNotRotated() {
        board.addGizmo(GizmoKind.CIRCLE, "C2", 12, 12);
        editor.selectAll(List.of("C1", "C2"), false);
        var undoable = editor.history().undoable();
        assertThat(editor.rotateSelected()).isFalse();
        assertThat(lastMessage()).contains("look the same turned");
        assertThat(editor.history().undoable()).isEqualTo(undoable);
    }

    @Test
    void copyingAGroupTakesTheConnectionsInsideItAndPastesUnderFreshNamesAllSelected() {
        editor.selectAll(List.of("S1", "T1"), false);
        String text = editor.clipboard().copySelected().orElseThrow();
        assertThat(text).contains("Square S1 2 2", "Triangle T1 4 2", "Connect S1 T1").doesNotContain("C1");
        assertThat(lastMessage()).isEqualTo("Copied S1 and T1");

        assertThat(editor.clipboard().paste(text)).isTrue();
        List<String> pasted = editor.selection();
        assertThat(pasted).hasSize(2).doesNotContain("S1", "T1");
        assertThat(board.connections()).contains(new Connection(TriggerSource.gizmo(pasted.get(0)), pasted.get(1)));
        assertThat(board.keyBindings()).contains(new KeyBinding(KeyEvent.VK_SPACE, KeyEdge.DOWN, pasted.get(1)));
        Gizmo s = gizmo(pasted.get(0));
        Gizmo t = gizmo(pasted.get(1));
        assertThat(t.x() - s.x()).as("the group keeps its shape").isEqualTo(2);
        assertThat(t.y()).isEqualTo(s.y());
        editor.undo();
        assertThat(board.gizmos()).hasSize(4);
    }

    @Test
    void cutAndDuplicateActOnTheWholeGroup() {
        editor.selectAll(List.of("S1", "S2", "B1"), false);
        assertThat(editor.clipboard().duplicateSelected()).isTrue();
        assertThat(editor.selection()).hasSize(3).doesNotContain("S1", "S2", "B1");
        assertThat(board.gizmos()).hasSize(6);
        assertThat(board.balls()).hasSize(2);

        editor.selectAll(List.of("S1", "S2", "B1"), false);
        String text = editor.clipboard().cutSelected().orElseThrow();
        assertThat(text).contains("Square S1", "Square S2", "Ball B1");
        assertThat(board.gizmo("S1")).isEmpty();
        assertThat(board.ball("B1")).isEmpty();
        assertThat(editor.history().undoable()).contains("Cut S1, S2 and B1");
        editor.undo();
        assertThat(board.gizmo("S1")).isPresent();
        assertThat(board.ball("B1")).isPresent();
    }

    @Test
    void aContextMenuOnOneOfTheGroupKeepsTheGroup() {
        editor.selectAll(List.of("S1", "S2"), false);
        assertThat(editor.selectAt(2.5, 2.5)).isTrue();
        assertThat(editor.selection()).containsExactly("S2", "S1");
        assertThat(editor.selectAt(10.5, 10.5)).isTrue();
        assertThat(editor.selection()).containsExactly("C1");
    }

    @Test
    void longListsAreCounted() {
        assertThat(Editor.listed(List.of("A"))).isEqualTo("A");
        assertThat(Editor.listed(List.of("A", "B"))).isEqualTo("A and B");
        assertThat(Editor.listed(List.of("A", "B", "C", "D"))).isEqualTo("A, B, C and D");
        assertThat(Editor.listed(List.of("A", "B", "C", "D", "E"))).isEqualTo("A, B, C and 2 more");
    }
}
