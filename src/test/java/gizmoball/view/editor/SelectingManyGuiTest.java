package gizmoball.view.editor;

import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.editor.Tool;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.view.Gui;
import java.awt.event.KeyEvent;
import java.util.List;
import javax.swing.JLabel;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Issue 23 through the real window: a rubber band and Shift+click select many, the group is dragged, nudged and
 * deleted; a bumper tool dragged fills a rectangle; an absorber's handle resizes it; each undone from the Edit menu.
 */
class SelectingManyGuiTest {
    private BuildWindow w;

    @BeforeEach
    void open() {
        w = BuildWindow.open();
        onEdt(() -> {
            w.board.addGizmo(GizmoKind.SQUARE, "S1", 2, 2);
            w.board.addGizmo(GizmoKind.SQUARE, "S2", 3, 2);
            w.board.addGizmo(GizmoKind.CIRCLE, "C1", 10, 10);
            w.board.addAbsorber("A", 0, 18, 8, 20);
        });
    }

    @AfterEach
    void close() {
        if (w != null) {   // null when the test was skipped for want of a display
            w.close();
        }
    }

    private Gizmo gizmo(String name) {
        return onEdt(() -> w.board.gizmo(name).orElseThrow());
    }

    private List<String> selection() {
        return onEdt(() -> w.build.controller().selection());
    }

    @Test
    void aBandAndShiftClickSelectAndTheGroupMovesAndGoesAsOneUndoStepEach() {
        w.clickTool(Tool.SELECT);
        w.drag(1.5, 1.5, 3.5, 2.8);
        assertThat(selection()).containsExactly("S1", "S2");
        w.shiftClick(10.5, 10.5);
        assertThat(selection()).containsExactly("S1", "S2", "C1");
        String shown = onEdt(() -> EditorGui.find(w.build.properties(), JLabel.class, "selection").getText());
        assertThat(shown).contains("3 selected", "S1, S2, C1");

        w.dragCells(3, 2, 5, 3);
        assertThat(List.of(gizmo("S1").x(), gizmo("S2").x(), gizmo("C1").x(), gizmo("C1").y()))
                .containsExactly(4, 5, 12, 11);
        w.key(KeyEvent.VK_LEFT);
        assertThat(gizmo("S1").x()).isEqualTo(3);
        Gui.clickMenu(w.window.menus(), "Undo: Moved S1, S2 and C1 by (-1,0)");
        Gui.clickMenu(w.window.menus(), "Undo: Moved S1, S2 and C1 by (2,1)");
        assertThat(gizmo("S1").x()).isEqualTo(2);

        w.key(KeyEvent.VK_DELETE);
        assertThat(onEdt(() -> w.board.gizmos())).extracting(Gizmo::name).containsExactly("A");
        Gui.clickMenu(w.window.menus(), "Undo: Deleted S1, S2 and C1");
        assertThat(onEdt(() -> w.board.gizmos())).hasSize(4);
    }

    /**
     * Issue 40 item 10: long names of many selected are listed as far as the label's two lines hold, then "and N
     * more", never cut; and Shift+click says in the status line what it did and how many are now selected.
     */
    @Test
    void manyLongNamesFitTheSummaryAndShiftClickSaysWhatItDid() {
        onEdt(() -> {
            for (int i = 0; i < 8; i++) {
                w.board.addGizmo(GizmoKind.CIRCLE, "AVeryLongBumperName" + i, 2 * i, 14);
            }
        });
        w.clickTool(Tool.SELECT);
        w.drag(0.2, 13.8, 16.8, 15.2);
        assertThat(selection()).hasSize(8);
        w.shiftClick(10.5, 10.5);
        assertThat(w.status()).isEqualTo("Added C1: 9 selected");

        JLabel label = onEdt(() -> EditorGui.find(w.build.properties(), JLabel.class, "selection"));
        String shown = onEdt(label::getText);
        assertThat(shown).contains("9 selected", "AVeryLongBumperName0").containsPattern(" and [1-9] more ");
        JLabel probe = onEdt(() -> {
            JLabel p = new JLabel(shown);
            p.setFont(label.getFont());
            return p;
        });
        assertThat(onEdt(() -> probe.getPreferredSize().height)).as("the summary's height")
                .isLessThanOrEqualTo(onEdt(label::getHeight));
        w.shiftClick(10.5, 10.5);
        assertThat(w.status()).isEqualTo("Took out C1: 8 selected");
    }

    @Test
    void aDraggedBumperToolFillsTheRectangleAndAnAbsorberHandleResizesIt() {
        w.clickTool(Tool.TRIANGLE);
        w.dragCells(1, 1, 4, 3);
        assertThat(onEdt(() -> w.board.gizmos().stream().filter(g -> g.kind() == GizmoKind.TRIANGLE).count()))
                .as("4 x 3 cells but S1 and S2").isEqualTo(10);
        Gui.clickMenu(w.window.menus(), "Undo: Placed T1, T2, T3 and 7 more");
        assertThat(onEdt(() -> w.board.gizmos())).hasSize(4);

        w.clickTool(Tool.SELECT);
        w.clickCell(4, 19);
        assertThat(selection()).containsExactly("A");
        w.drag(8, 19, 12.2, 19);
        Gizmo a = gizmo("A");
        assertThat(List.of(a.x(), a.y(), a.width(), a.height())).containsExactly(0, 18, 12, 2);
        Gui.clickMenu(w.window.menus(), "Undo: Resized A to 12x2 at (0,18)");
        assertThat(gizmo("A").width()).isEqualTo(8);
    }
}
