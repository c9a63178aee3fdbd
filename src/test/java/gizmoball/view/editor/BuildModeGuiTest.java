package gizmoball.view.editor;

import gizmoball.boardfile.BoardContents;
import gizmoball.editor.Tool;
import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;
import gizmoball.session.GameSession;
import gizmoball.session.Mode;
import gizmoball.view.BoardPainter;
import gizmoball.view.Gui;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JTabbedPane;
import javax.swing.JTextField;
import javax.swing.KeyStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Point;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JComponent;
import javax.swing.JButton;
import java.awt.Rectangle;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

/**
 * Build mode in a real window (under Xvfb in CI): palette buttons are clicked, mouse events arrive at the
 * board view at the pixels of board cells, keys go through the board view's key listener, menus are clicked.
 * One test drives the real pointer with java.awt.Robot. Skipped, with the reason, without a display.
 */
class BuildModeGuiTest {
    private BuildWindow w;
    private Board board;
    private GameSession session;

    @BeforeEach
    void openWindowInBuildMode() {
        w = BuildWindow.open();
        board = w.board;
        session = w.session;
    }

    @AfterEach
    void close() {
        if (w != null) {
            w.close();
        }
    }

    @Test
    void robotClicksOnThePaletteAndTheBoardPlaceASquare() throws Exception {
        // Other tests' windows may still be on the screen: the real pointer must land on this one.
        onEdt(() -> {
            w.window.setAlwaysOnTop(true);
            w.window.toFront();
        });
        Robot robot = new Robot();
        robot.setAutoDelay(20);
        robot.waitForIdle();
        Point button = BuildWindow.centreOnScreen(w.toolButton(Tool.SQUARE));
        Point cell = w.cellOnScreen(6, 9);
        robot.mouseMove(button.x, button.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        await("the Square tool is chosen", () -> w.build.controller().tool() == Tool.SQUARE);
        robot.mouseMove(cell.x, cell.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);

        await("S1 is on the board", () -> board.gizmo("S1").isPresent());
        Gizmo s1 = board.gizmo("S1").orElseThrow();
        assertThat(List.of(s1.x(), s1.y())).containsExactly(6, 9);
        assertThat(session.isModified()).isTrue();
    }

    @Test
    void everyKindIsPlacedByClickingItsToolAndTheBoard() {
        w.clickTool(Tool.SQUARE);
        w.clickCell(1, 1);
        w.clickTool(Tool.CIRCLE);
        w.clickCell(3, 1);
        w.clickTool(Tool.TRIANGLE);
        w.clickCell(5, 1);
        w.clickTool(Tool.LEFT_FLIPPER);
        w.clickCell(1, 5);
        w.clickTool(Tool.RIGHT_FLIPPER);
        w.clickCell(5, 5);
        w.clickTool(Tool.ABSORBER);
        w.dragCells(0, 19, 19, 19);
        w.clickTool(Tool.BALL);
        w.drag(10.5, 10.5, 11.5, 8.5);

        assertThat(onEdt(() -> board.gizmos().stream().map(Gizmo::kind).toList())).containsExactly(
                GizmoKind.SQUARE, GizmoKind.CIRCLE, GizmoKind.TRIANGLE, GizmoKind.LEFT_FLIPPER,
                GizmoKind.RIGHT_FLIPPER, GizmoKind.ABSORBER);
        Gizmo absorber = board.gizmo("A1").orElseThrow();
        assertThat(List.of(absorber.x(), absorber.y(), absorber.width(), absorber.height()))
                .containsExactly(0, 19, 20, 1);
        // A drag of (+1, -2) L from the ball's centre gives (10, -20) L/s at 10 L/s per L dragged.
        var ball = board.ball("B1").orElseThrow();
        assertThat(ball.position().x()).isCloseTo(10.5, within(1e-9));
        assertThat(ball.velocity().x()).isCloseTo(10, within(1e-9));
        assertThat(ball.velocity().y()).isCloseTo(-20, within(1e-9));
        assertThat(session.isModified()).isTrue();
    }

    @Test
    void draggingAGizmoMovesItAndRotateAndDeleteActOnTheClickedGizmo() {
        w.clickTool(Tool.TRIANGLE);
        w.clickCell(2, 2);
        w.clickTool(Tool.SELECT);
        w.dragCells(2, 2, 12, 7);
        assertThat(onEdt(() -> List.of(board.gizmo("T1").orElseThrow().x(), board.gizmo("T1").orElseThrow().y())))
                .containsExactly(12, 7);

        w.clickTool(Tool.ROTATE);
        w.clickCell(12, 7);
        assertThat(board.gizmo("T1").orElseThrow().rotation()).isEqualTo(1);

        w.clickTool(Tool.DELETE);
        w.clickCell(12, 7);
        assertThat(board.gizmos()).isEmpty();
    }

    @Test
    void connectingTwoGizmosShowsTheConnectionInTheProperties() {
        w.clickTool(Tool.CIRCLE);
        w.clickCell(4, 4);
        w.clickTool(Tool.LEFT_FLIPPER);
        w.clickCell(8, 8);
        w.clickTool(Tool.CONNECT);
        w.clickCell(4, 4);
        w.clickCell(9, 9);
        JMenuItem connect = onEdt(() -> EditorGui.showingMenuItem("order.connect"));
        onEdt(() -> connect.doClick(0));

        assertThat(board.connections()).containsExactly(new Connection(TriggerSource.gizmo("C1"), "LF1"));
        JList<?> links = onEdt(() -> EditorGui.find(w.build.properties(), JList.class, "links"));
        assertThat(onEdt(() -> links.getModel().getSize())).isEqualTo(1);
        assertThat(onEdt(() -> links.getModel().getElementAt(0).toString())).isEqualTo("C1 \u2192 LF1");
    }

    @Test
    void aKeyBoundInBuildModeSwingsTheFlipperInPlay() {
        w.clickTool(Tool.LEFT_FLIPPER);
        w.clickCell(3, 15);
        w.clickTool(Tool.KEY_CONNECT);
        w.clickCell(3, 15);
        w.key(KeyEvent.VK_SPACE);
        JMenuItem down = onEdt(() -> EditorGui.showingMenuItem("edge.down"));
        onEdt(() -> down.doClick(0));

        assertThat(board.keyBindings()).containsExactly(new KeyBinding(KeyEvent.VK_SPACE, KeyEdge.DOWN, "LF1"));
        onEdt(() -> session.setMode(Mode.PLAY));
        onEdt(() -> {
            board.keyDown(KeyEvent.VK_SPACE);
            board.tick(0.1);
        });
        FlipperView lf1 = (FlipperView) board.gizmo("LF1").orElseThrow();
        assertThat(lf1.angleFromRest()).isCloseTo(90, within(1e-9));
    }

    @Test
    void keyConnectsPopupOffersTheGizmosActionsAndADelay() {
        w.clickTool(Tool.ABSORBER);
        w.clickCell(2, 18);
        w.clickTool(Tool.KEY_CONNECT);
        w.clickCell(2, 18);
        w.key(KeyEvent.VK_SPACE);
        List<String> offered = onEdt(() -> Stream.of("action.default", "action.fire", "action.flash", "action.raise")
                .filter(name -> {
                    try {
                        EditorGui.showingMenuItem(name);
                        return true;
                    } catch (AssertionError absent) {
                        return false;
                    }
                }).toList());
        assertThat(offered).as("an absorber fires (its own action, not offered twice) or flashes; it does not rise")
                .containsExactly("action.default", "action.flash");
        assertThat(onEdt(() -> EditorGui.showingMenuItem("action.default").getText())).isEqualTo("its own: fire");
        onEdt(() -> EditorGui.showingMenuItem("action.flash").doClick(0));
        JTextField delay = onEdt(() -> Gui.find(EditorGui.showingMenuItem("edge.down").getParent(), JTextField.class,
                f -> "order.delay".equals(f.getName())).orElseThrow());
        onEdt(() -> delay.setText("0.25"));
        onEdt(() -> EditorGui.showingMenuItem("edge.down").doClick(0));

        assertThat(board.keyBindings()).containsExactly(new KeyBinding(KeyEvent.VK_SPACE, KeyEdge.DOWN, "A1",
                Order.of(Action.FLASH).after(0.25)));
    }

    /** Issue 40 item 11: Connect's popup offers a spawner's own action once ("its own: spawn"), not again. */
    @Test
    void connectsPopupOffersTheOwnActionOnce() {
        onEdt(() -> {
            board.addGizmo(GizmoKind.SQUARE, "S9", 2, 2);
            board.addGizmo(GizmoKind.SPAWNER, "SP", 6, 2);
        });
        w.clickTool(Tool.CONNECT);
        w.clickCell(2, 2);
        w.clickCell(6, 2);
        assertThat(onEdt(() -> EditorGui.showingMenuItem("action.default").getText())).isEqualTo("its own: spawn");
        assertThatThrownBy(() -> onEdt(() -> EditorGui.showingMenuItem("action.spawn")))
                .hasMessageContaining("no showing menu item action.spawn");
        onEdt(() -> EditorGui.showingMenuItem("action.flash").getText());
    }

    @Test
    void undoAndRedoFromTheEditMenu() {
        w.clickTool(Tool.SQUARE);
        w.clickCell(1, 1);
        w.clickCell(2, 1);
        JMenuItem undo = EditorGui.menuItemNamed(w.window.menus(), "edit.undo");
        JMenuItem redo = EditorGui.menuItemNamed(w.window.menus(), "edit.redo");
        assertThat(onEdt(redo::isEnabled)).isFalse();

        onEdt(() -> undo.doClick(0));
        assertThat(board.gizmos()).extracting(Gizmo::name).containsExactly("S1");
        assertThat(onEdt(redo::isEnabled)).isTrue();
        onEdt(() -> redo.doClick(0));
        assertThat(board.gizmos()).extracting(Gizmo::name).containsExactly("S1", "S2");
    }

    @Test
    void aRefusedOverlapLeavesTheBoardAsItWasAndSaysWhyOnTheStatusLine() {
        w.clickTool(Tool.SQUARE);
        w.clickCell(5, 5);
        BoardContents before = onEdt(() -> BoardContents.of(board));
        w.clickTool(Tool.RIGHT_FLIPPER);
        w.clickCell(4, 4);

        assertThat(onEdt(() -> BoardContents.of(board))).isEqualTo(before);
        assertThat(w.status()).contains("overlap").contains("S1");
    }

    @Test
    void gravityTypedIntoThePropertiesIsValidated() {
        JTextField gravity = onEdt(() -> EditorGui.find(w.build.properties(), JTextField.class, "gravity"));
        onEdt(() -> {
            gravity.setText("strong");
            gravity.postActionEvent();
        });
        assertThat(board.gravity()).isEqualTo(Board.DEFAULT_GRAVITY);
        assertThat(w.status()).contains("not a number");

        onEdt(() -> {
            gravity.setText("10");
            gravity.postActionEvent();
        });
        assertThat(board.gravity()).isEqualTo(10);
    }

    @Test
    void aGizmosColourIsChosenInThePropertiesShownInTheSwatchAndUndone() {
        w.clickTool(Tool.SQUARE);
        w.clickCell(3, 3);
        w.clickTool(Tool.SELECT);
        w.clickCell(3, 3);
        JTextField colour = onEdt(() -> EditorGui.find(w.build.properties(), JTextField.class, "gizmo.colour"));
        JLabel swatch = onEdt(() -> EditorGui.find(w.build.properties(), JLabel.class, "gizmo.colour.swatch"));
        assertThat(onEdt(() -> colour.getText())).as("no colour of its own").isEmpty();
        assertThat(onEdt(() -> swatch.getBackground())).isEqualTo(BoardPainter.colourOf(GizmoKind.SQUARE));

        onEdt(() -> {
            colour.setText("#99B3FF");
            colour.postActionEvent();
        });
        assertThat(board.gizmos().get(0).colour()).contains(new Rgb(0x99, 0xb3, 0xff));
        assertThat(onEdt(() -> colour.getText())).isEqualTo("#99b3ff");
        assertThat(onEdt(() -> swatch.getBackground())).isEqualTo(new Color(0x99b3ff));

        onEdt(() -> {
            colour.setText("pink");
            colour.postActionEvent();
        });
        assertThat(w.status()).contains("not #rrggbb");
        assertThat(board.gizmos().get(0).colour()).contains(new Rgb(0x99, 0xb3, 0xff));

        onEdt(() -> EditorGui.find(w.build.properties(), JButton.class, "gizmo.colour.reset").doClick(0));
        assertThat(board.gizmos().get(0).colour()).isEmpty();
        onEdt(() -> w.build.controller().undo());
        assertThat(board.gizmos().get(0).colour()).contains(new Rgb(0x99, 0xb3, 0xff));
        onEdt(() -> w.build.controller().undo());
        assertThat(board.gizmos().get(0).colour()).isEmpty();
    }

    @Test
    void inPlayModeTheMouseDoesNotEdit() {
        w.clickTool(Tool.SQUARE);
        onEdt(() -> session.setMode(Mode.PLAY));
        w.clickCell(3, 3);
        assertThat(board.gizmos()).isEmpty();
        assertThat(onEdt(w.build.editMenu()::isEnabled)).isFalse();
    }


    @Test
    void theEditMenuSitsAfterFileAndItsShortcutsClashWithNoOtherMenu() {
        JMenuBar menus = w.window.menus();
        assertThat(onEdt(() -> menus.getMenu(1))).isSameAs(w.build.editMenu());
        List<KeyStroke> accelerators = onEdt(() -> {
            List<KeyStroke> all = new ArrayList<>();
            for (int i = 0; i < menus.getMenuCount(); i++) {
                for (int j = 0; j < menus.getMenu(i).getItemCount(); j++) {
                    JMenuItem item = menus.getMenu(i).getItem(j);
                    if (item != null && item.getAccelerator() != null) {
                        all.add(item.getAccelerator());
                    }
                }
            }
            return all;
        });
        assertThat(accelerators).contains(KeyStroke.getKeyStroke(KeyEvent.VK_Z, InputEvent.CTRL_DOWN_MASK))
                .doesNotHaveDuplicates();
    }

    /** Issue 12 item 9: build mode never resizes the window, and at 700 x 480 every tool and field is in reach. */
    @Test
    void buildModeKeepsTheWindowsSizeAndASmallWindowReachesEveryToolAndField() {
        Dimension small = new Dimension(700, 480);
        onEdt(() -> w.session.setMode(Mode.PLAY));
        onEdt(() -> w.window.setSize(small));
        await("the small window", () -> w.window.getSize().equals(small));
        onEdt(() -> w.session.setMode(Mode.BUILD));
        await("build layout", () -> w.build.palette().isShowing() && w.panel.getWidth() > 0);
        onEdt(() -> w.window.validate());
        assertThat(onEdt(() -> w.window.getSize())).isEqualTo(small);
        List<JComponent> controls = new ArrayList<>();
        for (Tool tool : Tool.values()) {
            controls.add(w.toolButton(tool));
        }
        controls.add(onEdt(() -> EditorGui.find(w.build.properties(), JButton.class, "board.apply")));
        controls.add(onEdt(() -> EditorGui.find(w.build.properties(), JButton.class, "links.remove")));
        for (JComponent c : controls) {
            // The Board and Selection tabs: the one holding the control brought forward, as a click on it would.
            onEdt(() -> {
                JTabbedPane tabs = EditorGui.find(w.build.properties(), JTabbedPane.class, "properties.tabs");
                for (int i = 0; i < tabs.getTabCount(); i++) {
                    if (javax.swing.SwingUtilities.isDescendingFrom(c, tabs.getComponentAt(i))) {
                        tabs.setSelectedIndex(i);
                    }
                }
                w.window.validate();
            });
            onEdt(() -> c.scrollRectToVisible(new Rectangle(c.getSize())));
            assertThat(onEdt(() -> c.getVisibleRect().getSize())).as(c.getName() + " scrolled into view")
                    .isEqualTo(onEdt(() -> c.getSize()));
        }
        onEdt(() -> w.session.setMode(Mode.PLAY));
        assertThat(onEdt(() -> w.window.getSize())).isEqualTo(small);
    }

}
