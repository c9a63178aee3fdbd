package gizmoball.app;

import gizmoball.session.GameSession;
import gizmoball.session.Mode;
import gizmoball.view.editor.BoardInput;
import gizmoball.editor.Editor;
import gizmoball.editor.Tool;
import gizmoball.view.BoardPanel;
import gizmoball.view.GameWindow;
import gizmoball.view.editor.BuildOverlay;
import gizmoball.view.editor.EdgePopup;
import gizmoball.view.editor.EditMenu;
import gizmoball.view.editor.PalettePanel;
import gizmoball.view.editor.PropertiesPanel;
import gizmoball.view.editor.WindowFit;

import javax.swing.JMenuBar;
import java.awt.Cursor;
import java.util.function.BooleanSupplier;

/**
 * Adds build mode to a game window: palette (west), properties (east), the Edit menu, the overlay and the
 * mouse and key handling on the board view. Everything acts only while the session is in BUILD mode.
 */
public final class BuildModeInstaller {
    private BuildModeInstaller() {
    }

    /** The installed parts, for tests and for anyone who wants to drive the editor directly. */
    public record BuildMode(Editor controller, PalettePanel palette, PropertiesPanel properties,
                            EditMenu editMenu) { }

    public static BuildMode install(GameWindow window, GameSession session) {
        BoardPanel panel = window.boardPanel();
        BooleanSupplier building = () -> session.mode() == Mode.BUILD;

        Editor controller = Editor.of(session.board());
        controller.setMessageSink(window.statusLine()::showMessage);
        controller.addEditListener(session::markModified);
        controller.addStateListener(panel::repaint);
        Runnable cursor = () -> panel.setCursor(building.getAsBoolean() ? cursorFor(controller.tool())
                : Cursor.getDefaultCursor());
        controller.addStateListener(cursor);

        PalettePanel palette = new PalettePanel(controller);
        PropertiesPanel properties = new PropertiesPanel(controller, panel::requestFocusInWindow);
        window.setSidePanels(palette, properties);

        EditMenu editMenu = new EditMenu(controller, window, building);
        JMenuBar menus = window.menus();
        menus.add(editMenu, Math.min(1, menus.getMenuCount()));
        menus.revalidate();

        panel.addOverlay(new BuildOverlay(controller, building));
        EdgePopup edgePopup = new EdgePopup(controller, panel);
        BoardInput.attach(controller, panel, building, edgePopup::show);

        WindowFit fit = new WindowFit(window);
        session.addModeListener(mode -> {
            fit.modeChanged(mode);
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
}
