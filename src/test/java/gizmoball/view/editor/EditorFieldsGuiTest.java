package gizmoball.view.editor;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.editor.Tool;
import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.TriggerSource;
import gizmoball.view.Gui;
import java.awt.Window;
import java.awt.event.KeyEvent;
import java.util.Optional;
import javax.swing.JMenuItem;
import javax.swing.JTextField;
import javax.swing.border.LineBorder;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Issue 12, items 7, 8, 11 and 14: the properties fields, rotating what cannot turn, binding down and up at once. */
class EditorFieldsGuiTest {
    private BuildWindow w;

    @BeforeEach
    void open() {
        w = BuildWindow.open();
    }

    @AfterEach
    void close() {
        if (w != null) {
            w.close();
        }
    }

    private JTextField field(String name) {
        return onEdt(() -> EditorGui.find(w.build.properties(), JTextField.class, name));
    }

    private static boolean markedRed(JTextField f) {
        return f.getBorder() instanceof LineBorder line && line.getLineColor().equals(NumberField.MARK);
    }

    @Test
    void aBadNumberIsMarkedWithItsReasonAndNothingIsApplied() {
        JTextField gravity = field("gravity");
        JTextField mu = field("mu");
        onEdt(() -> {
            gravity.setText("abc");
            mu.setText("1e400");
            gravity.postActionEvent();
        });
        assertThat(onEdt(() -> markedRed(gravity))).isTrue();
        assertThat(onEdt(() -> markedRed(mu))).as("1e400 is beyond a double: no board-file number").isTrue();
        assertThat(onEdt(() -> gravity.getToolTipText())).contains("\"abc\" is not a number");
        assertThat(w.status()).contains("\"abc\" is not a number");
        assertThat(w.board.gravity()).isEqualTo(Board.DEFAULT_GRAVITY);
        assertThat(w.board.mu()).isEqualTo(Board.DEFAULT_MU);

        onEdt(() -> {
            gravity.setText("20");
            mu.setText("0.03");
            mu.postActionEvent();
        });
        assertThat(w.board.gravity()).isEqualTo(20.0);
        assertThat(w.board.mu()).isEqualTo(0.03);
        assertThat(onEdt(() -> markedRed(gravity) || markedRed(mu))).isFalse();
    }

    /** Issue 23, item 15: one rule: a value the model refuses stays in its field, outlined, its reason the tooltip. */
    @Test
    void aValueTheBoardRefusesStaysInItsFieldMarkedWithTheBoardsReason() {
        JTextField gravity = field("gravity");
        JTextField mu = field("mu");
        onEdt(() -> {
            gravity.setText("30");
            mu.setText("-1");
            mu.postActionEvent();
        });

        assertThat(onEdt(() -> mu.getText())).isEqualTo("-1");
        assertThat(onEdt(() -> gravity.getText())).isEqualTo("30");
        assertThat(onEdt(() -> markedRed(mu) && markedRed(gravity))).isTrue();
        assertThat(onEdt(() -> mu.getToolTipText())).isEqualTo(w.status());
        assertThat(onEdt(() -> markedRed(field("mu2")))).as("mu2 was not changed").isFalse();
        assertThat(w.board.mu()).isEqualTo(Board.DEFAULT_MU);
        assertThat(w.board.gravity()).isEqualTo(Board.DEFAULT_GRAVITY);

        onEdt(() -> {
            mu.setText("0.03");
            mu.postActionEvent();
        });
        assertThat(w.board.mu()).isEqualTo(0.03);
        assertThat(onEdt(() -> markedRed(mu))).isFalse();
    }

    @Test
    void aColourThatIsNoColourStaysInItsFieldMarkedWithTheReason() {
        onEdt(() -> w.board.addGizmo(GizmoKind.SQUARE, "S1", 3, 3));
        onEdt(() -> w.build.controller().select("S1"));
        JTextField colour = field("gizmo.colour");
        String normalTip = onEdt(() -> colour.getToolTipText());
        onEdt(() -> {
            colour.setText("green");
            colour.postActionEvent();
        });

        assertThat(onEdt(() -> colour.getText())).isEqualTo("green");
        assertThat(onEdt(() -> markedRed(colour))).isTrue();
        assertThat(onEdt(() -> colour.getToolTipText())).contains("is not #rrggbb");

        onEdt(() -> {
            colour.setText("#00ff00");
            colour.postActionEvent();
        });
        assertThat(onEdt(() -> markedRed(colour))).isFalse();
        assertThat(onEdt(() -> colour.getToolTipText())).isEqualTo(normalTip);
    }

    @Test
    void enterAndEscapeInAFieldGiveTheKeyboardBackToTheBoard() {
        JTextField gravity = field("gravity");
        onEdt(() -> {
            w.window.toFront();
            gravity.requestFocusInWindow();
        });
        await("the gravity field has the keyboard", gravity::isFocusOwner);
        onEdt(() -> {
            gravity.setText("20");
            gravity.postActionEvent();
        });
        await("the board has the keyboard after Enter", w.panel::isFocusOwner);

        onEdt(() -> gravity.requestFocusInWindow());
        await("the gravity field has the keyboard again", gravity::isFocusOwner);
        onEdt(() -> {
            gravity.setText("abc");
            gravity.dispatchEvent(new KeyEvent(gravity, KeyEvent.KEY_PRESSED, System.currentTimeMillis(), 0,
                    KeyEvent.VK_ESCAPE, KeyEvent.CHAR_UNDEFINED));
        });
        await("the board has the keyboard after Esc", w.panel::isFocusOwner);
        assertThat(onEdt(() -> gravity.getText())).as("Esc puts the board's value back").isEqualTo("20");
        assertThat(onEdt(() -> markedRed(gravity))).isFalse();
    }

    @Test
    void rotatingACircleIsRefusedAndLeavesTheBoardUnchanged() {
        w.clickTool(Tool.CIRCLE);
        w.clickCell(4, 4);
        onEdt(() -> w.session.saved(java.nio.file.Path.of("unchanged.txt")));
        w.clickTool(Tool.ROTATE);
        w.clickCell(4, 4);
        assertThat(w.status()).isEqualTo("C1 is a circle: it looks the same turned, so it cannot be rotated");
        assertThat(onEdt(() -> w.session.isModified())).isFalse();
        assertThat(onEdt(() -> w.build.controller().history().undoable())).contains("Placed C1 at (4,4)");
    }

    @Test
    void keyConnectBindsDownAndUpInOnePass() {
        onEdt(() -> w.board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 3, 15));
        w.clickTool(Tool.KEY_CONNECT);
        w.clickCell(3, 15);
        w.key(KeyEvent.VK_Z);
        await("the edge popup", () -> popupItem("edge.both").isPresent());
        onEdt(() -> popupItem("edge.both").orElseThrow().doClick(0));
        assertThat(onEdt(() -> w.board.keyBindings())).containsExactlyInAnyOrder(
                new KeyBinding(KeyEvent.VK_Z, KeyEdge.DOWN, "LF"), new KeyBinding(KeyEvent.VK_Z, KeyEdge.UP, "LF"));
        onEdt(() -> w.build.controller().undo());
        assertThat(onEdt(() -> w.board.keyBindings())).as("one undo step for both").isEmpty();
    }

    /** Issue 12 item 12: the refusal reads the same on hover and on click, and names no would-be gizmo. */
    @Test
    void aRefusedPlacementSaysTheSameOnHoverAndOnClick() {
        w.clickTool(Tool.SQUARE);
        w.clickCell(2, 4);
        w.clickTool(Tool.TRIANGLE);
        w.hover(2.5, 4.5);
        String onHover = w.status();
        assertThat(onHover).startsWith("a triangle at (2,4) would overlap").contains("S1");
        w.clickCell(2, 4);
        assertThat(w.status()).isEqualTo(onHover);
        assertThat(onEdt(() -> w.board.gizmos())).hasSize(1);
    }

    /** Issue 12 item 13. */
    @Test
    void theEditMenuSaysWhatUndoTakesBackAndOffersRotateAndDeleteOnlyForASelection() {
        JMenuItem undo = EditorGui.menuItemNamed(w.window.menus(), "edit.undo");
        JMenuItem rotate = EditorGui.menuItemNamed(w.window.menus(), "edit.rotateselection");
        JMenuItem delete = EditorGui.menuItemNamed(w.window.menus(), "edit.deleteselection");
        assertThat(onEdt(() -> rotate.isEnabled() || delete.isEnabled())).as("nothing selected").isFalse();

        w.clickTool(Tool.SQUARE);
        w.clickCell(2, 4);
        assertThat(onEdt(() -> undo.getText())).isEqualTo("Undo: Placed S1 at (2,4)");
        assertThat(onEdt(() -> rotate.isEnabled() && delete.isEnabled())).as("S1 selected").isTrue();

        w.clickTool(Tool.SELECT);
        w.click(-0.5, 10);
        assertThat(onEdt(() -> w.build.controller().selected())).contains(TriggerSource.OuterWalls.NAME);
        assertThat(onEdt(() -> rotate.isEnabled() || delete.isEnabled())).as("the outer walls selected").isFalse();
        onEdt(() -> undo.doClick(0));
        assertThat(onEdt(() -> EditorGui.menuItemNamed(w.window.menus(), "edit.redo").getText()))
                .isEqualTo("Redo: Placed S1 at (2,4)");
    }

    /** Issue 12 item 15: the rows of the Selection panel stay where they are, whatever is selected. */
    @Test
    void theSelectionPanelDoesNotJumpWhenTheSelectionChanges() {
        onEdt(() -> {
            w.board.addGizmo(GizmoKind.SQUARE, "S1", 2, 2);
            w.board.addBall("B1", 10.5, 10.5, 0, 0);
        });
        javax.swing.JList<?> links = onEdt(() -> EditorGui.find(w.build.properties(), javax.swing.JList.class, "links"));
        java.util.List<java.awt.Rectangle> placed = new java.util.ArrayList<>();
        for (String name : new String[] {null, "S1", "B1", TriggerSource.OuterWalls.NAME}) {
            onEdt(() -> w.build.controller().select(name));
            // Selecting nothing brings the Board tab forward: the Selection tab is then one click away.
            onEdt(() -> EditorGui.find(w.build.properties(), javax.swing.JTabbedPane.class, "properties.tabs")
                    .setSelectedIndex(1));
            onEdt(() -> w.build.properties().validate());
            placed.add(onEdt(() -> javax.swing.SwingUtilities.convertRectangle(links.getParent(),
                    links.getParent().getBounds(), w.build.properties())));
        }
        assertThat(placed).as("the links list, selecting nothing, S1, B1, OuterWalls").containsOnly(placed.get(0));
    }

    private static Optional<JMenuItem> popupItem(String name) {
        for (Window window : Window.getWindows()) {
            Optional<JMenuItem> item = Gui.find(window, JMenuItem.class, i -> name.equals(i.getName()) && i.isShowing());
            if (item.isPresent()) {
                return item;
            }
        }
        return Optional.empty();
    }
}
