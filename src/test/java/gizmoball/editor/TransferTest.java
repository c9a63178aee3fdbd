package gizmoball.editor;

import gizmoball.model.gizmo.Setting;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardContents;
import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Issue 23, the author's actions: type a position, rename, copy, cut, paste, duplicate; each one undo step. */
class TransferTest extends EditorFixture {
    @BeforeEach
    void setUp() {
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 4, 10);
        board.addGizmo(GizmoKind.CIRCLE, "C1", 3, 4);
        board.addGizmo(GizmoKind.TRIANGLE, "T1", 9, 9);
        board.rotate("T1");
        board.setColour("T1", Optional.of(Rgb.of(0x99b3ff)));
        board.connect(TriggerSource.gizmo("C1"), "LF");
        board.connect(TriggerSource.OUTER_WALLS, "LF");
        board.connect(TriggerSource.gizmo("T1"), "T1");
        board.bindKey(90, KeyEdge.DOWN, "LF");
    }

    @Test
    void aTypedPositionMovesTheGizmoAndUndoesInOneStep() {
        assertThat(editor.properties().moveGizmoTo("C1", 12, 2)).isTrue();
        assertThat(gizmo("C1").x()).isEqualTo(12);
        assertThat(gizmo("C1").y()).isEqualTo(2);

        assertThat(editor.properties().moveGizmoTo("C1", 9, 9)).as("onto T1").isFalse();
        assertThat(gizmo("C1").x()).isEqualTo(12);
        editor.undo();
        assertThat(gizmo("C1").x()).isEqualTo(3);
    }

    @Test
    void renamingKeepsEverythingThatNamedTheGizmo() {
        BoardContents before = BoardContents.of(board);
        editor.select("LF");

        assertThat(editor.properties().rename("LF", "Left")).isTrue();

        assertThat(board.gizmo("LF")).isEmpty();
        assertThat(gizmo("Left").x()).isEqualTo(4);
        assertThat(board.connections()).contains(new Connection(TriggerSource.gizmo("C1"), "Left"),
                new Connection(TriggerSource.OUTER_WALLS, "Left"));
        assertThat(board.keyBindings()).containsExactly(new KeyBinding(90, KeyEdge.DOWN, "Left"));
        assertThat(editor.selected()).contains("Left");
        editor.undo();
        assertThat(BoardContents.of(board)).isEqualTo(before);
    }

    @Test
    void aRenamedGizmoKeepsItsTurnsColourAndItsConnectionToItself() {
        assertThat(editor.properties().rename("T1", "Ramp")).isTrue();

        assertThat(gizmo("Ramp").rotation()).isEqualTo(1);
        assertThat(gizmo("Ramp").colour()).contains(Rgb.of(0x99b3ff));
        assertThat(board.connections()).contains(new Connection(TriggerSource.gizmo("Ramp"), "Ramp"));
    }

    @Test
    void aNameTakenOrWithSpacesIsRefusedAndChangesNothing() {
        BoardContents before = BoardContents.of(board);
        Optional<String> lastStep = editor.history().undoable();
        assertThat(editor.properties().rename("LF", "C1")).isFalse();
        assertThat(editor.properties().rename("LF", "two words")).isFalse();
        assertThat(editor.lastRefusal()).hasValueSatisfying(r -> assertThat(r).contains("one word"));
        assertThat(editor.properties().rename("LF", "OuterWalls")).isFalse();
        assertThat(BoardContents.of(board)).isEqualTo(before);
        assertThat(editor.history().undoable()).isEqualTo(lastStep);
    }

    @Test
    void aPairTypedInThePropertiesIsOneUndoStepAndFollowsARenameAndACopyOfBoth() {
        board.addGizmo(GizmoKind.PORTAL, "P1", 1, 1);
        board.addGizmo(GizmoKind.PORTAL, "P2", 15, 1);
        assertThat(editor.properties().set("P1", Setting.Pair.with("P2"))).isTrue();
        assertThat(pair("P2")).contains("P1");
        assertThat(editor.properties().set("P1", Setting.Pair.with("C1"))).as("a circle is no portal").isFalse();
        assertThat(messages).last().asString().contains("only portals are paired: C1 is a circle");

        assertThat(editor.properties().rename("P2", "Exit")).isTrue();
        assertThat(pair("P1")).contains("Exit");
        editor.selectAll(List.of("P1", "Exit"), false);
        String text = editor.clipboard().copySelected().orElseThrow();
        assertThat(editor.clipboard().paste(text)).isTrue();
        assertThat(pair("P2")).as("the copies (fresh names P2, P3) are each other's pair").contains("P3");
        assertThat(pair("P1")).contains("Exit");

        assertThat(editor.properties().set("P1", Setting.Pair.with(""))).isTrue();
        assertThat(pair("Exit")).isEmpty();
        editor.undo();
        assertThat(pair("Exit")).contains("P1");
    }

    private Optional<String> pair(String portal) {
        return ((gizmoball.model.gizmo.PortalView) gizmo(portal)).pair();
    }

    @Test
    void copyThenPasteOnAnotherBoardPutsItWhereItWasUnderAFreshName() {
        editor.select("T1");
        String text = editor.clipboard().copySelected().orElseThrow();
        Board other = new Board();
        Editor second = Editor.of(other);

        assertThat(second.clipboard().paste(text)).isTrue();

        Gizmo pasted = other.gizmos().get(0);
        assertThat(pasted.name()).isEqualTo("T1");
        assertThat(pasted.x()).isEqualTo(9);
        assertThat(pasted.rotation()).isEqualTo(1);
        assertThat(pasted.colour()).contains(Rgb.of(0x99b3ff));
        assertThat(other.connections()).as("its connection to itself comes along")
                .containsExactly(new Connection(TriggerSource.gizmo("T1"), "T1"));
        assertThat(second.selected()).contains("T1");
    }

    @Test
    void pastingOntoTheSameBoardTakesTheNearestFreePlaceAndAFreshName() {
        editor.select("C1");
        String text = editor.clipboard().copySelected().orElseThrow();

        assertThat(editor.clipboard().paste(text)).isTrue();

        Gizmo pasted = gizmo("C2");
        assertThat(Math.max(Math.abs(pasted.x() - 3), Math.abs(pasted.y() - 4))).isEqualTo(1);
        assertThat(board.connections()).as("the connection to LF was to outside the copy")
                .doesNotContain(new Connection(TriggerSource.gizmo("C2"), "LF"));
        editor.undo();
        assertThat(board.gizmo("C2")).isEmpty();
    }

    @Test
    void aCopiedFlipperTakesItsKeyAlong() {
        editor.select("LF");
        assertThat(editor.clipboard().duplicateSelected()).isTrue();

        assertThat(board.keyBindings()).contains(new KeyBinding(90, KeyEdge.DOWN, "LF1"));
        assertThat(editor.selected()).contains("LF1");
        assertThat(lastMessage()).isEqualTo("Duplicated LF as LF1");
    }

    @Test
    void cutCopiesAndDeletesInOneStep() {
        editor.select("C1");
        String text = editor.clipboard().cutSelected().orElseThrow();

        assertThat(board.gizmo("C1")).isEmpty();
        assertThat(text).contains("Circle C1 3 4");
        assertThat(editor.clipboard().paste(text)).isTrue();
        assertThat(gizmo("C1").x()).as("back where it was, its name free again").isEqualTo(3);
        editor.undo();
        editor.undo();
        assertThat(gizmo("C1").x()).isEqualTo(3);
        assertThat(board.connections()).contains(new Connection(TriggerSource.gizmo("C1"), "LF"));
    }

    @Test
    void textThatIsNoBoardIsNotPasted() {
        BoardContents before = BoardContents.of(board);
        assertThat(editor.clipboard().paste("hello world")).isFalse();
        assertThat(editor.clipboard().paste("")).isFalse();
        assertThat(editor.lastRefusal()).hasValueSatisfying(r -> assertThat(r).startsWith("Nothing to paste"));
        assertThat(BoardContents.of(board)).isEqualTo(before);
    }

    @Test
    void aBallCopiesWithItsVelocity() {
        board.addBall("B", 15.5, 3.5, 2, -1);
        editor.select("B");
        assertThat(editor.clipboard().duplicateSelected()).isTrue();

        assertThat(board.ball("B1").orElseThrow().velocity().x()).isEqualTo(2.0);
    }

    /** The context menu's part in the editor: select what is under the pointer, connect from the selection. */
    @Test
    void aContextMenuSelectsWhatIsUnderThePointerAndConnectsFromIt() {
        assertThat(editor.selectAt(3.5, 4.5)).isTrue();
        assertThat(editor.selected()).contains("C1");
        assertThat(editor.selectAt(15.5, 15.5)).as("nothing there").isFalse();
        assertThat(editor.selected()).isEmpty();

        editor.selectAt(9.5, 9.5);
        editor.connectFromSelected();
        assertThat(editor.tool()).isEqualTo(Tool.CONNECT);
        editor.press(3.5, 4.5);
        editor.release(3.5, 4.5);
        editor.links().chooseConnection();
        assertThat(board.connections()).contains(new Connection(TriggerSource.gizmo("T1"), "C1"));
    }
}
