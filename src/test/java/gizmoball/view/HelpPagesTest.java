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

/** The help pages say what the game has, and the README says the same (no display needed). */
class HelpPagesTest {
    @Test
    void theBuildModePageListsEveryToolWithItsKeyAsTheReadmeDoes() throws Exception {
        String page = HelpPages.buildMode();
        String readme = Files.readString(Path.of("README.md"));
        for (Tool tool : Tool.values()) {
            assertThat(page).contains(tool.labelWithShortcut(), tool.hint());
            assertThat(readme).as("README's build-mode table").contains(tool.labelWithShortcut());
        }
    }

    /** Issue 23: the author's actions are listed in Help and in the README alike. */
    @Test
    void theBuildModePageAndTheReadmeListTheAuthorsActions() throws Exception {
        String page = HelpPages.buildMode();
        String readme = Files.readString(Path.of("README.md"));
        for (String action : new String[] {"Ctrl+C", "Ctrl+X", "Ctrl+V", "Ctrl+D", "Name", "Cell x, y",
                "Open recent", "Right-click", "Connect from here"}) {
            assertThat(page).contains(action);
            assertThat(readme).contains(action);
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

        String page = HelpPages.howToPlay(menus, board);

        assertThat(page).contains(KeyEvent.getKeyText(KeyEvent.VK_Z) + ": left flipper LF (hold)");
        assertThat(page).contains("Start (Ctrl+G), Reset (Ctrl+Shift+R), About");
    }

    @Test
    void howToPlaySaysWhatTheBoardsGameIs() throws Exception {
        assertThat(HelpPages.howToPlay(new JMenuBar(), new Board())).contains("it is a sandbox, which never ends");
        Board game = BoardFiles.load(Path.of("boards", "default.txt"));
        assertThat(HelpPages.howToPlay(new JMenuBar(), game)).contains("A game of 3 balls: a ball captured by the"
                + " drain (A) is lost", "An extra ball at 1500 points.", "circle 50, triangle 25, square 10");
    }

    @Test
    void aBoardWithoutKeysSaysSo() {
        assertThat(HelpPages.howToPlay(new JMenuBar(), new Board())).contains("This board binds no keys.");
    }
}
