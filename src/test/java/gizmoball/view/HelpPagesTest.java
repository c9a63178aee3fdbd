package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.editor.Tool;
import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.KeyStroke;
import org.junit.jupiter.api.Test;

/** The help pages say what the game has, and the documents say the same (no display needed). */
class HelpPagesTest {
    @Test
    void theBuildModePageListsEveryToolWithItsKeyAsTheDocumentsDo() throws Exception {
        String page = HelpPages.buildMode();
        String documented = Files.readString(Path.of("docs", "build-mode.md"));
        for (Tool tool : Tool.values()) {
            assertThat(page).contains(tool.labelWithShortcut(), tool.hint());
            assertThat(documented).as("docs/build-mode.md's table").contains(tool.labelWithShortcut());
        }
    }

    /** Issue 23: the author's actions are listed in Help and in docs/build-mode.md alike. */
    @Test
    void theBuildModePageAndTheDocumentsListTheAuthorsActions() throws Exception {
        String page = HelpPages.buildMode();
        String documented = Files.readString(Path.of("docs", "build-mode.md"));
        for (String action : new String[] {"Ctrl+C", "Ctrl+X", "Ctrl+V", "Ctrl+D", "Name", "Cell x, y",
                "Open recent", "Right-click", "Connect from here"}) {
            assertThat(page).contains(action);
            assertThat(documented).contains(action);
        }
    }

    @Test
    void howToPlayListsTheBoardsKeysAndEveryMenuItemWithItsShortcut() {
        Board board = new Board();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 6, 16);
        board.bindKey(KeyEvent.VK_Z, KeyEdge.DOWN, "LF");
        board.bindKey(KeyEvent.VK_Z, KeyEdge.UP, "LF");
        JMenuBar menus = new JMenuBar();
        JMenu game = new JMenu("Game");
        JMenuItem start = new JMenuItem("Start");
        start.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_G, InputEvent.CTRL_DOWN_MASK));
        game.add(start);
        JMenuItem reset = new JMenuItem("Reset");
        reset.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_R, InputEvent.CTRL_DOWN_MASK | InputEvent.SHIFT_DOWN_MASK));
        game.add(reset);
        game.add(new JMenuItem("About"));
        menus.add(game);

        String page = HelpPages.howToPlay(menus, board, "");

        assertThat(page).contains(KeyEvent.getKeyText(KeyEvent.VK_Z) + ": left flipper LF (hold)");
        assertThat(page).contains("Start (Ctrl+G), Reset (Ctrl+Shift+R), About");
    }

    @Test
    void howToPlaySaysWhatTheBoardsGameIs() throws Exception {
        assertThat(HelpPages.howToPlay(new JMenuBar(), new Board(), "")).contains("it is a sandbox, which never ends");
        Board game = BoardFiles.load(Path.of("boards", "default.txt"));
        assertThat(HelpPages.howToPlay(new JMenuBar(), game, "")).contains("A game of 3 balls: a ball captured by the"
                + " drain (Drain) is lost", "An extra ball at 3000 points.", "circle 50, triangle 25, square 10");
    }

    @Test
    void aBoardWithoutKeysSaysSo() {
        assertThat(HelpPages.howToPlay(new JMenuBar(), new Board(), "")).contains("This board binds no keys.");
    }
}
