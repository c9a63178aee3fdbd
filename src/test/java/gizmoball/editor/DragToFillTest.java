package gizmoball.editor;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Issue 23, drag to fill: a bumper tool dragged fills the rectangle, the taken cells skipped, in one undo step. */
class DragToFillTest extends EditorFixture {
    @BeforeEach
    void setUp() {
        board.addGizmo(GizmoKind.CIRCLE, "C1", 3, 2);
    }

    private List<String> cellsOf(GizmoKind kind) {
        return board.gizmos().stream().filter(g -> g.kind() == kind).map(g -> g.x() + "," + g.y()).toList();
    }

    @Test
    void theDragPreviewsWhatFitsAndTheReleasePlacesItAllInOneUndoStep() {
        editor.setTool(Tool.SQUARE);
        editor.press(1.5, 1.5);
        editor.drag(4.5, 2.5);
        Preview.Group preview = (Preview.Group) editor.preview().orElseThrow();
        assertThat(preview.fits()).isTrue();
        assertThat(preview.parts()).as("(3,2) is taken by C1: skipped").extracting(p -> {
            Preview.Footprint f = (Preview.Footprint) p;
            return f.x() + "," + f.y();
        }).containsExactly("1,1", "2,1", "3,1", "4,1", "1,2", "2,2", "4,2");
        editor.release(4.5, 2.5);

        assertThat(cellsOf(GizmoKind.SQUARE)).containsExactly("1,1", "2,1", "3,1", "4,1", "1,2", "2,2", "4,2");
        assertThat(board.gizmos()).extracting(Gizmo::name).contains("S1", "S7");
        assertThat(editor.selection()).hasSize(7).startsWith("S1");
        assertThat(editor.history().undoable()).contains("Placed S1, S2, S3 and 4 more");
        editor.undo();
        assertThat(cellsOf(GizmoKind.SQUARE)).isEmpty();
        editor.redo();
        assertThat(cellsOf(GizmoKind.SQUARE)).hasSize(7);
    }

    @Test
    void aDragUpAndLeftFillsFromThePressedCellAndFlippersTileByTheirSize() {
        editor.setTool(Tool.TRIANGLE);
        editor.press(6.5, 6.5);
        editor.drag(5.5, 5.5);
        editor.release(5.5, 5.5);
        assertThat(cellsOf(GizmoKind.TRIANGLE)).containsExactlyInAnyOrder("6,6", "5,6", "6,5", "5,5");

        editor.setTool(Tool.LEFT_FLIPPER);
        editor.press(10.5, 10.5);
        editor.drag(13.5, 11.5);
        editor.release(13.5, 11.5);
        assertThat(cellsOf(GizmoKind.LEFT_FLIPPER)).containsExactly("10,10", "12,10");
    }

    @Test
    void aClickStillPlacesOneAndARectangleWithNoRoomIsRefusedWithTheReason() {
        editor.setTool(Tool.CIRCLE);
        editor.press(8.5, 8.5);
        editor.release(8.5, 8.5);
        assertThat(cellsOf(GizmoKind.CIRCLE)).containsExactly("3,2", "8,8");
        assertThat(lastMessage()).isEqualTo("Placed C2 at (8,8)");

        board.addGizmo(GizmoKind.SQUARE, "S9", 4, 2);
        Optional<String> undoable = editor.history().undoable();
        editor.press(3.5, 2.5);
        editor.drag(4.5, 2.5);
        assertThat(editor.preview().orElseThrow().problem()).contains(
                "No room here: every place in the rectangle is taken or off the board");
        editor.release(4.5, 2.5);
        assertThat(lastMessage()).startsWith("No room here");
        assertThat(editor.history().undoable()).isEqualTo(undoable);
        assertThat(cellsOf(GizmoKind.CIRCLE)).containsExactly("3,2", "8,8");
    }
}
