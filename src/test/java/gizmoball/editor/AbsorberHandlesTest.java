package gizmoball.editor;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.TriggerSource;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Issue 23, resizing an absorber by its handles: one undo step; a size the board refuses says why. */
class AbsorberHandlesTest extends EditorFixture {
    @BeforeEach
    void setUp() {
        board.addAbsorber("A", 2, 17, 10, 19);
        board.addGizmo(GizmoKind.SQUARE, "S1", 14, 17);
        board.connect(TriggerSource.gizmo("A"), "A");
        editor.setTool(Tool.SELECT);
        editor.select("A");
    }

    private List<Integer> bounds() {
        Gizmo a = board.gizmo("A").orElseThrow();
        return List.of(a.x(), a.y(), a.width(), a.height());
    }

    @Test
    void aSelectedAbsorberHasHandlesAtItsCornersAndEdgeMiddles() {
        assertThat(editor.handles()).hasSize(8)
                .contains(new Handle(2, 17, true, true, false, false), new Handle(10, 19, false, false, true, true),
                        new Handle(6, 19, false, false, false, true), new Handle(10, 18, false, false, true, false));
        editor.select("S1");
        assertThat(editor.handles()).as("a square has none").isEmpty();
        editor.selectAll(List.of("A", "S1"), false);
        assertThat(editor.handles()).as("nor has a group").isEmpty();
    }

    @Test
    void draggingACornerHandleResizesToTheNearestGridLinesInOneUndoStep() {
        editor.press(10.1, 19.2);
        editor.drag(12.3, 21.2);
        assertThat(editor.preview()).contains(new Preview.Footprint(2, 17, 10, 4, Optional.of(
                "an absorber at (2,17) would leave the board: cell (2,20) is outside it")));
        editor.drag(12.3, 19.8);
        assertThat(editor.preview()).contains(new Preview.Footprint(2, 17, 10, 3, Optional.empty()));
        editor.release(12.3, 19.8);
        assertThat(bounds()).containsExactly(2, 17, 10, 3);
        assertThat(board.connections()).as("it is the same absorber").hasSize(1);
        assertThat(editor.history().undoable()).contains("Resized A to 10x3 at (2,17)");
        editor.undo();
        assertThat(bounds()).containsExactly(2, 17, 8, 2);
    }

    @Test
    void anEdgeHandleMovesOneEdgeAndARefusedSizeSaysWhyAndChangesNothing() {
        editor.press(2, 18);
        editor.release(0.4, 18);
        assertThat(bounds()).containsExactly(0, 17, 10, 2);

        Optional<String> undoable = editor.history().undoable();
        editor.press(10, 18);
        editor.drag(15.2, 18);
        assertThat(lastMessage()).contains("would overlap gizmo S1");
        editor.release(15.2, 18);
        assertThat(bounds()).containsExactly(0, 17, 10, 2);

        editor.press(5, 19);
        editor.drag(5, 16.8);
        assertThat(lastMessage()).contains("at least one cell wide and high");
        editor.release(5, 16.8);
        assertThat(bounds()).containsExactly(0, 17, 10, 2);
        assertThat(editor.history().undoable()).isEqualTo(undoable);
    }

    @Test
    void aPressInsideTheAbsorberAwayFromItsHandlesStillMovesIt() {
        editor.press(4.5, 17.5);
        editor.release(4.5, 16.5);
        assertThat(bounds()).containsExactly(2, 16, 8, 2);
    }
}
