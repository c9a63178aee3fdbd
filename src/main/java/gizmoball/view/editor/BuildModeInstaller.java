package gizmoball.view.editor;

import gizmoball.controller.GameSession;
import gizmoball.controller.Mode;
import gizmoball.controller.editor.BoardInput;
import gizmoball.controller.editor.BuildController;
import gizmoball.controller.editor.Tool;
import gizmoball.model.KeyEdge;
import gizmoball.view.BoardPanel;
import gizmoball.view.GameWindow;

import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JPopupMenu;
import javax.swing.event.PopupMenuEvent;
import javax.swing.event.PopupMenuListener;
import java.awt.Cursor;
import java.awt.geom.Point2D;
import java.util.function.BooleanSupplier;

/**
 * Adds build mode to a game window: palette (west), properties (east), the Edit menu, the overlay and the
 * mouse and key handling on the board view. Everything acts only while the session is in BUILD mode.
 */
public final class BuildModeInstaller {
    private BuildModeInstaller() {
    }

    /** The installed parts, for tests and for anyone who wants to drive the editor directly. */
    public record BuildMode(BuildController controller, PalettePanel palette, PropertiesPanel properties,
                            EditMenu editMenu) { }

    public static BuildMode install(GameWindow window) {
        GameSession session = window.session();
        BoardPanel panel = window.boardPanel();
        BooleanSupplier building = () -> session.mode() == Mode.BUILD;

        BuildController controller = new BuildController(session.board());
        controller.setMessageSink(window.statusLine()::showMessage);
        controller.addEditListener(session::markModified);
        controller.addStateListener(panel::repaint);
        Runnable cursor = () -> panel.setCursor(building.getAsBoolean() ? cursorFor(controller.tool())
                : Cursor.getDefaultCursor());
        controller.addStateListener(cursor);

        PalettePanel palette = new PalettePanel(controller);
        PropertiesPanel properties = new PropertiesPanel(controller);
        window.setSidePanels(palette, properties);

        EditMenu editMenu = new EditMenu(controller, window, building);
        JMenuBar menus = window.menus();
        menus.add(editMenu, Math.min(1, menus.getMenuCount()));
        menus.revalidate();

        panel.addOverlay(new BuildOverlay(controller, building));
        BoardInput.attach(controller, panel, building, () -> chooseEdge(controller, panel));

        session.addModeListener(mode -> {
            controller.cancel();
            editMenu.update();
            cursor.run();
            panel.repaint();
        });
        return new BuildMode(controller, palette, properties, editMenu);
    }

    /** Crosshair where a click places something, a hand where it acts on what is under it. */
    private static Cursor cursorFor(Tool tool) {
        if (tool.kind().isPresent() || tool == Tool.BALL) {
            return Cursor.getPredefinedCursor(Cursor.CROSSHAIR_CURSOR);
        }
        return Cursor.getPredefinedCursor(tool == Tool.SELECT ? Cursor.DEFAULT_CURSOR : Cursor.HAND_CURSOR);
    }

    /** Key Connect's last step: a popup at the gizmo asks whether the binding acts on key down or key up. */
    private static void chooseEdge(BuildController controller, BoardPanel panel) {
        JPopupMenu popup = new JPopupMenu("Key edge");
        JMenuItem down = new JMenuItem("On key down (press)");
        JMenuItem up = new JMenuItem("On key up (release)");
        down.setName("edge.down");
        up.setName("edge.up");
        down.addActionListener(e -> {
            popup.setVisible(false);
            controller.chooseEdge(KeyEdge.DOWN);
        });
        up.addActionListener(e -> {
            popup.setVisible(false);
            controller.chooseEdge(KeyEdge.UP);
        });
        popup.add(down);
        popup.add(up);
        popup.addPopupMenuListener(new PopupMenuListener() {
            @Override
            public void popupMenuWillBecomeVisible(PopupMenuEvent e) {
                // nothing to prepare
            }

            @Override
            public void popupMenuWillBecomeInvisible(PopupMenuEvent e) {
                // a choice was made or it was cancelled: handled by the items and popupMenuCanceled
            }

            @Override
            public void popupMenuCanceled(PopupMenuEvent e) {
                controller.cancel();
            }
        });
        Point2D at = controller.selectedGizmo()
                .map(g -> panel.transform().toScreen(g.x() + g.width(), g.y()))
                .orElse(new Point2D.Double(panel.getWidth() / 2.0, panel.getHeight() / 2.0));
        popup.show(panel, (int) at.getX(), (int) at.getY());
    }
}
