package gizmoball.view.editor;

import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.TriggerSource;
import javax.swing.JMenuItem;
import gizmoball.view.Gui;
import java.awt.Toolkit;
import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.StringSelection;
import javax.swing.JTextField;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Issue 23, the author's actions through the real window: the Edit menu's clipboard, Name and Cell fields. */
class AuthorActionsGuiTest {
    private BuildWindow w;

    @BeforeEach
    void open() {
        w = BuildWindow.open();
        onEdt(() -> {
            w.board.addGizmo(GizmoKind.CIRCLE, "C1", 3, 4);
            w.board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 6, 16);
            w.board.connect(TriggerSource.gizmo("C1"), "LF");
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

    @Test
    void copyPutsBoardLinesOnTheClipboardAndPasteAndUndoWorkThroughTheEditMenu() throws Exception {
        w.clickTool(gizmoball.editor.Tool.SELECT);
        w.clickCell(3, 4);
        Gui.clickMenu(w.window.menus(), "Copy");
        String copied = (String) Toolkit.getDefaultToolkit().getSystemClipboard().getData(DataFlavor.stringFlavor);
        assertThat(copied).contains("Circle C1 3 4");

        Gui.clickMenu(w.window.menus(), "Paste");
        assertThat(onEdt(() -> w.board.gizmo("C2"))).isPresent();
        assertThat(onEdt(() -> w.window.getTitle())).endsWith("*");
        Gui.clickMenu(w.window.menus(), "Undo: Pasted C2");
        assertThat(onEdt(() -> w.board.gizmo("C2"))).isEmpty();

        onEdt(() -> Toolkit.getDefaultToolkit().getSystemClipboard()
                .setContents(new StringSelection("# from a text editor\nSquare Wall 10 10\n"), null));
        Gui.clickMenu(w.window.menus(), "Paste");
        assertThat(gizmo("S1").x()).as("typed board lines paste, under a fresh name").isEqualTo(10);
    }

    @Test
    void theNameAndCellFieldsRenameAndMoveTheSelection() {
        onEdt(() -> w.build.controller().select("C1"));
        JTextField name = onEdt(() -> EditorGui.find(w.build.properties(), JTextField.class, "selection.name"));
        JTextField x = onEdt(() -> EditorGui.find(w.build.properties(), JTextField.class, "gizmo.x"));
        JTextField y = onEdt(() -> EditorGui.find(w.build.properties(), JTextField.class, "gizmo.y"));
        assertThat(onEdt(() -> name.getText())).isEqualTo("C1");
        assertThat(onEdt(() -> x.getText() + "," + y.getText())).isEqualTo("3,4");

        onEdt(() -> {
            name.setText("Kicker");
            name.postActionEvent();
        });
        assertThat(onEdt(() -> w.board.connections())).extracting(c -> c.source().name()).containsExactly("Kicker");
        onEdt(() -> {
            x.setText("12");
            y.setText("2");
            y.postActionEvent();
        });
        assertThat(gizmo("Kicker").x()).isEqualTo(12);
        assertThat(gizmo("Kicker").y()).isEqualTo(2);

        onEdt(() -> {
            x.setText("6");
            y.setText("16");
            y.postActionEvent();
        });
        assertThat(onEdt(() -> x.getText())).as("refused: LF is there; the value stays").isEqualTo("6");
        assertThat(onEdt(() -> RefusedValue.isMarked(x) && RefusedValue.isMarked(y))).isTrue();
        assertThat(gizmo("Kicker").x()).isEqualTo(12);
    }

    private void rightClick(double x, double y) {
        onEdt(() -> {
            java.awt.geom.Point2D p = w.panel.transform().toScreen(x, y);
            w.panel.dispatchEvent(new java.awt.event.MouseEvent(w.panel, java.awt.event.MouseEvent.MOUSE_PRESSED,
                    System.currentTimeMillis(), java.awt.event.InputEvent.BUTTON3_DOWN_MASK, (int) p.getX(),
                    (int) p.getY(), 1, true, java.awt.event.MouseEvent.BUTTON3));
        });
    }

    private javax.swing.JMenuItem contextItem(String name) {
        return onEdt(() -> java.util.Arrays.stream(java.awt.Window.getWindows()).filter(java.awt.Window::isShowing)
                .flatMap(win -> Gui.find(win, javax.swing.JMenuItem.class, i -> name.equals(i.getName())
                        && i.isShowing()).stream()).findFirst()
                .or(() -> Gui.find(w.window.getLayeredPane(), javax.swing.JMenuItem.class,
                        i -> name.equals(i.getName()) && i.isShowing()))
                .orElseThrow(() -> new AssertionError("no " + name + " showing")));
    }

    @Test
    void theContextMenuActsOnWhatIsUnderThePointer() {
        rightClick(6.5, 16.5);
        assertThat(onEdt(() -> w.build.controller().selected())).contains("LF");
        javax.swing.JMenuItem rotate = contextItem("context.rotate");
        assertThat(onEdt(rotate::isEnabled)).isTrue();
        onEdt(() -> rotate.doClick(0));
        assertThat(gizmo("LF").rotation()).isEqualTo(1);

        rightClick(15.5, 2.5);
        assertThat(onEdt(() -> contextItem("context.delete").isEnabled())).as("nothing under the pointer").isFalse();
        assertThat(onEdt(() -> contextItem("context.paste").isEnabled())).isTrue();
        onEdt(() -> contextItem("context.paste").getParent().setVisible(false));

        rightClick(6.5, 16.5);
        onEdt(() -> contextItem("context.connectfromhere").doClick(0));
        w.clickCell(3, 4);
        JMenuItem connect = onEdt(() -> EditorGui.showingMenuItem("order.connect"));
        onEdt(() -> connect.doClick(0));
        assertThat(onEdt(() -> w.board.connections())).contains(new gizmoball.model.loop.Connection(
                TriggerSource.gizmo("LF"), "C1"));
        Gui.clickMenu(w.window.menus(), "Undo: Connected LF \u2192 C1");
    }
}
