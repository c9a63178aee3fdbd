package gizmoball.app;

import gizmoball.boardfile.BoardContents;
import gizmoball.session.GameSession;
import gizmoball.session.Mode;
import gizmoball.view.editor.BoardContextMenu;
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
import gizmoball.view.editor.SidePane;

import gizmoball.controller.PlayTest;
import gizmoball.controller.PlayTestCommand;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.KeyStroke;
import javax.swing.JScrollPane;
import java.awt.Cursor;
import java.awt.Dimension;
import java.awt.Insets;
import java.awt.Rectangle;
import java.awt.Toolkit;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.function.BooleanSupplier;

/**
 * Adds build mode to a game window: palette (west), properties (east), the Edit and Test menus, the overlay and the
 * mouse and key handling on the board view. Everything acts only while the session is in BUILD mode.
 */
public final class BuildModeInstaller {
    private BuildModeInstaller() {
    }

    /** The installed parts, for tests and for anyone who wants to drive the editor directly. */
    public record BuildMode(Editor controller, PalettePanel palette, PropertiesPanel properties,
                            EditMenu editMenu, JMenu testMenu) { }

    /** Pixels of board wanted beside the labelled palette and the properties before the palette turns compact. */
    private static final int MIN_BOARD = 480;
    /** The smallest board worth building on (12 px per L): the window is never made smaller than to show it. */
    private static final int SMALLEST_BOARD = 240;

    public static BuildMode install(GameWindow window, GameSession session) {
        BoardPanel panel = window.boardPanel();
        BooleanSupplier building = () -> session.mode() == Mode.BUILD;

        Editor controller = Editor.of(session.board());
        controller.setMessageSink(window.statusLine()::showMessage);
        controller.addEditListener(() -> session.designEdited(BoardContents::sameDesign));
        controller.addStateListener(panel::repaint);
        Runnable cursor = () -> panel.setCursor(building.getAsBoolean() ? cursorFor(controller.tool())
                : Cursor.getDefaultCursor());
        controller.addStateListener(cursor);

        PalettePanel palette = PalettePanel.of(controller);
        PropertiesPanel properties = PropertiesPanel.of(controller, panel::requestFocusInWindow);
        // Each side scrolls when the window is too short for it, so that a small window keeps every tool and
        // field in reach; the window itself is never resized for build mode (the player chose its size).
        JScrollPane west = SidePane.scrolling(palette);
        JScrollPane east = SidePane.scrolling(properties);
        window.setSidePanels(west, east);
        openWideEnoughForBuildMode(window, west.getPreferredSize().width + east.getPreferredSize().width);
        // Below this width the labelled palette would leave the board less than MIN_BOARD pixels: icons only.
        int compactBelow = palette.getPreferredSize().width + properties.getPreferredSize().width + MIN_BOARD;
        // ... or the west side is too short for the labelled column: every tool stays in sight, none below a fold.
        Runnable fitPalette = () -> palette.setCompact(window.getWidth() < compactBelow
                || (west.getHeight() > 0 && west.getHeight() < palette.labelledHeight()));
        ComponentAdapter refit = new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                fitPalette.run();
            }
        };
        window.addComponentListener(refit);
        west.addComponentListener(refit);
        fitPalette.run();
        // Measured once the window is whole and laid out: other features add rows above or below the board.
        window.addWindowListener(new WindowAdapter() {
            @Override
            public void windowOpened(WindowEvent e) {
                window.setMinimumSize(minimumSize(window, palette, west, east));
                fitPalette.run();
            }
        });

        EditMenu editMenu = EditMenu.of(controller, window, building);
        JMenuBar menus = window.menus();
        menus.add(editMenu, Math.min(1, menus.getMenuCount()));
        JMenu testMenu = testMenu(window, session);
        menus.add(testMenu, Math.min(2, menus.getMenuCount()));
        menus.revalidate();

        panel.addOverlay(new BuildOverlay(controller, building));
        EdgePopup edgePopup = EdgePopup.of(controller, panel);
        BoardContextMenu contextMenu = new BoardContextMenu(controller, panel, properties::focusName);
        BoardInput.attach(controller, panel, building, edgePopup::show, contextMenu::open);

        session.addModeListener(mode -> {
            controller.cancel();
            editMenu.update();
            testMenu.setEnabled(building.getAsBoolean());
            cursor.run();
            panel.repaint();
        });
        return new BuildMode(controller, palette, properties, editMenu, testMenu);
    }

    /**
     * Build mode's Test menu: Play-test (Ctrl+L) plays the design {@link PlayTest#GAMES} times with the lab's
     * autoplayer and idle player in the background and shows what came of it; asked again while it plays, it shows
     * the running one. Enabled in build mode only.
     */
    private static JMenu testMenu(GameWindow window, GameSession session) {
        JMenu menu = new JMenu("Test");
        menu.setMnemonic(KeyEvent.VK_T);
        JMenuItem playTest = new JMenuItem("Play-test\u2026");
        playTest.setName("test.playtest");
        playTest.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_L, InputEvent.CTRL_DOWN_MASK));
        playTest.setToolTipText("Play the board " + PlayTest.GAMES + " times with an autoplayer and " + PlayTest.GAMES
                + " with a player who only launches: scores, seconds per ball, gizmos never hit, a heat map");
        PlayTestCommand command = new PlayTestCommand(window, session::boardToSave, session::boardName);
        playTest.addActionListener(e -> command.run());
        menu.add(playTest);
        menu.setEnabled(session.mode() == Mode.BUILD);
        return menu;
    }

    /**
     * The window opens as wide as play mode's board plus both sides (within the screen), so that entering build
     * mode never has to resize it; a size the player chose later, or that the settings restore, is kept.
     */
    private static void openWideEnoughForBuildMode(GameWindow window, int sides) {
        Rectangle screen = window.getGraphicsConfiguration().getBounds();
        Insets insets = Toolkit.getDefaultToolkit().getScreenInsets(window.getGraphicsConfiguration());
        int width = Math.min(window.getWidth() + sides, screen.width - insets.left - insets.right);
        window.setSize(width, Math.min(window.getHeight(), screen.height - insets.top - insets.bottom));
        window.setLocationRelativeTo(null);
    }

    /**
     * The smallest window in which build mode is whole: the compact palette, the properties and the smallest board
     * side by side (each side with room for its scroll bar), and the whole tool bar; as tall as that board, or the
     * compact palette if taller (every tool in sight), with everything the window has above and below the board view
     * (menus, tool bar, status line and whatever else).
     */
    private static Dimension minimumSize(GameWindow window, PalettePanel palette, JScrollPane west, JScrollPane east) {
        palette.setCompact(true);
        int bar = west.getVerticalScrollBar().getPreferredSize().width;
        int sides = west.getPreferredSize().width + east.getPreferredSize().width + 2 * bar;
        Insets frame = window.getInsets();
        int width = Math.max(window.toolBar().getPreferredSize().width, sides + SMALLEST_BOARD)
                + frame.left + frame.right;
        int aroundBoard = window.getHeight() - window.boardPanel().getHeight();
        return new Dimension(width, aroundBoard + Math.max(SMALLEST_BOARD, west.getPreferredSize().height));
    }

    /** Crosshair where a click places something, a hand where it acts on what is under it. */
    private static Cursor cursorFor(Tool tool) {
        if (tool.kind().isPresent() || tool == Tool.BALL) {
            return Cursor.getPredefinedCursor(Cursor.CROSSHAIR_CURSOR);
        }
        return Cursor.getPredefinedCursor(tool == Tool.SELECT ? Cursor.DEFAULT_CURSOR : Cursor.HAND_CURSOR);
    }
}
