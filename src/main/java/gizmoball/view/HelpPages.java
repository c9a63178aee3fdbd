package gizmoball.view;

import gizmoball.boardfile.Decimals;
import gizmoball.boardfile.KeyCodes;
import gizmoball.editor.Tool;
import gizmoball.model.Board;
import gizmoball.model.game.GameRules;
import gizmoball.model.game.Points;
import gizmoball.model.gizmo.GizmoKind;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Window;
import java.awt.event.InputEvent;
import java.util.List;
import java.util.Objects;
import java.util.stream.IntStream;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JEditorPane;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.KeyStroke;
import javax.swing.ScrollPaneConstants;

/**
 * Help > How to play and Help > Build mode. The lists in them (menus and their shortcuts, the board's keys,
 * the build tools and their keys) are read from the window's own menus, the board and {@link Tool}, the
 * same facts the documents' tables state, so a page cannot name a shortcut the game does not have.
 */
final class HelpPages {
    static final String HOW_TO_PLAY = "How to play";
    static final String BUILD_MODE = "Build mode";

    private HelpPages() {
    }

    /** @param settingsPlace where the settings and high scores are kept, as the page says it */
    static String howToPlay(JMenuBar menus, Board board, String settingsPlace) {
        List<String> keys = KeyHelp.describe(board);
        StringBuilder html = new StringBuilder("<html><body><h2>How to play</h2>")
                .append("<p>Press <b>Start</b> (Ctrl+G) and play with the board's keys. Holding a key keeps a")
                .append(" flipper up; keys reach the board while its window has the focus. <b>Stop</b> (Ctrl+H)")
                .append(" pauses, <b>Tick</b> (Ctrl+T) steps once while stopped, <b>Reset</b> (Ctrl+Shift+R)")
                .append(" puts the board back as loaded or built.</p><h3>The game</h3><p>")
                .append(escape(game(board.gameRules()))).append("</p><h3>Keys of this board</h3>");
        if (keys.isEmpty()) {
            html.append("<p>This board binds no keys.</p>");
        } else {
            html.append("<ul>");
            keys.forEach(k -> html.append("<li>").append(escape(k)).append("</li>"));
            html.append("</ul>");
        }
        html.append("<h3>Menus</h3><p>Every shortcut uses Ctrl, so no board key is shadowed.</p><table>");
        for (int i = 0; i < menus.getMenuCount(); i++) {
            JMenu menu = menus.getMenu(i);
            html.append("<tr><td valign='top'><b>").append(escape(menu.getText())).append("</b></td><td>")
                    .append(escape(String.join(", ", items(menu)))).append("</td></tr>");
        }
        html.append("</table><p>The title shows * while there are unsaved changes; New, Open, Reload and Quit")
                .append(" ask first.</p>");
        if (!settingsPlace.isEmpty()) {
            html.append("<h3>Settings and high scores</h3><p>").append(escape(settingsPlace)).append("</p>");
        }
        html.append("</body></html>");
        return html.toString();
    }

    /** What this board's game is, from its rules. */
    static String game(GameRules rules) {
        String scoring = "A real hit scores the gizmo's points (unless the board gives it its own: circle "
                + Points.defaultFor(GizmoKind.CIRCLE) + ", triangle " + Points.defaultFor(GizmoKind.TRIANGLE)
                + ", square " + Points.defaultFor(GizmoKind.SQUARE) + ", accelerator "
                + Points.defaultFor(GizmoKind.ACCELERATOR) + ", others 0; a sink scores its own points when it takes"
                + " a ball).";
        if (!rules.isGame()) {
            return "This board has no drain: it is a sandbox, which never ends. " + scoring;
        }
        return "A game of " + rules.ballsPerGame() + (rules.ballsPerGame() == 1 ? " ball" : " balls") + ": a ball"
                + " captured by the drain (" + String.join(", ", rules.drains().stream().sorted().toList())
                + ") is lost, and the next waits in the plunger (else in the drain) for its key; a plunger is pulled"
                + " while its key is held and launches faster the longer the hold."
                + (rules.extraBallAt().isPresent() ? " An extra ball at " + rules.extraBallAt().getAsLong()
                + " points." : "")
                + rules.nudge().map(n -> " " + KeyCodes.name(n.leftKey()) + ", " + KeyCodes.name(n.rightKey()) + " and "
                + KeyCodes.name(n.upKey()) + " nudge the table; " + rules.tilt().nudges() + " nudges within "
                + Decimals.format(rules.tilt().seconds()) + " s tilt it: flippers and plunger dead, no score, until"
                + " the ball drains.").orElse("")
                + (rules.ballSaveSeconds() > 0 ? " A ball lost within " + Decimals.format(rules.ballSaveSeconds())
                + " s of its launch is given back once." : "")
                + " " + scoring + " Game > New game (Ctrl+Shift+N) starts again; Game > Players starts a game for 1"
                + " to 4 players, taking turns ball by ball; Game > High"
                + " scores shows the board's ten best, whose games Watch plays again.";
    }

    static String buildMode() {
        StringBuilder html = new StringBuilder("<html><body><h2>Build mode</h2>")
                .append("<p>Switch with <b>Mode &gt; Build</b> (Ctrl+B). Pick a tool in the palette on the left")
                .append(" or press its key over the board; the properties are on the right, hints and refusals")
                .append(" in the status line. Green footprint: the gizmo would go there; red: refused.</p>")
                .append("<table><tr><th align='left'>tool (key)</th><th align='left'>mouse</th></tr>");
        for (Tool tool : Tool.values()) {
            html.append("<tr><td valign='top'>").append(escape(tool.labelWithShortcut())).append("</td><td>")
                    .append(escape(tool.hint())).append("</td></tr>");
        }
        html.append("</table><p><b>Selecting many:</b> with Select, drag from empty space: the rubber band")
                .append(" selects the gizmos it touches and the balls whose centres it holds; <b>Shift+click</b>")
                .append(" adds a gizmo or ball or takes it out (Shift+drag adds a band). Drag one of the group to")
                .append(" move them all; Rotate turns each that turns, in its own cells; Delete, the arrow keys,")
                .append(" Cut, Copy and Duplicate act on them all. With a bumper or flipper tool, <b>drag</b> to")
                .append(" fill the rectangle (the taken places are skipped). A selected absorber has")
                .append(" <b>handles</b> at its corners and edges: drag one to resize it. Each is one undo")
                .append(" step.</p>")
                .append("<p><b>Zoom</b>: Ctrl+wheel over the board zooms about the pointer, Ctrl+= and Ctrl+-")
                .append(" about the middle, <b>Ctrl+0</b> fits the whole board again (View menu); zoomed, the")
                .append(" wheel scrolls.</p>")
                .append("<p><b>Delete</b> deletes the selection, the <b>arrow keys</b> move it,")
                .append(" <b>Esc</b> or right-click cancels a half-done step; <b>Ctrl+Z</b> undo,")
                .append(" <b>Ctrl+Y</b> redo. Every edit can be undone.</p>")
                .append("<p><b>Ctrl+C</b> copies the selection, <b>Ctrl+X</b> cuts it, <b>Ctrl+V</b> pastes and")
                .append(" <b>Ctrl+D</b> duplicates it (Edit menu): what is copied is board-file text, so it pastes")
                .append(" into another window or a text editor, and board lines from a text editor paste here.")
                .append(" Pasted gizmos get fresh names, keep their connections to each other and their keys, and")
                .append(" go where they were if that is free, else at the nearest place where they fit.</p>")
                .append("<p>In the properties, <b>Name</b> renames the selection (its connections and keys")
                .append(" follow) and <b>Cell x, y</b> moves a gizmo to the cell typed (Enter applies either).")
                .append(" A value that is refused stays in its field, outlined in red, the reason as its")
                .append(" tooltip.</p><p><b>Right-click</b> on the board selects what is there and opens a")
                .append(" context menu: Rotate, Delete, Cut, Copy, Paste, Duplicate, Connect from here, Properties.")
                .append("</p><p><b>File &gt; Open recent</b> lists the last ten boards opened or saved.</p>")
                .append("<p><b>Test &gt; Play-test</b> (<b>Ctrl+L</b>) plays the board 100 times with an autoplayer")
                .append(" and 100 times launching only, in the background, then shows where the balls went, the")
                .append(" mean scores, how long a ball lasts and the gizmos never hit.</p>")
                .append("</body></html>");
        return html.toString();
    }

    /** "New (Ctrl+N)" for each item of the menu, submenus by name. */
    static List<String> items(JMenu menu) {
        return IntStream.range(0, menu.getItemCount()).mapToObj(menu::getItem)
                .filter(Objects::nonNull)
                .map(item -> item.getText() + shortcut(item)).toList();
    }

    private static String shortcut(JMenuItem item) {
        KeyStroke key = item instanceof JMenu ? null : item.getAccelerator();
        if (key == null) {
            return "";
        }
        String modifiers = InputEvent.getModifiersExText(key.getModifiers());
        return " (" + (modifiers.isEmpty() ? "" : modifiers + "+") + KeyCodes.name(key.getKeyCode()) + ")";
    }

    private static String escape(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }

    /** A modal page with a Close button (Esc closes it too). */
    static void show(Window owner, String title, String html) {
        JDialog dialog = new JDialog(owner, title, JDialog.ModalityType.APPLICATION_MODAL);
        dialog.setName("help");
        JEditorPane page = new JEditorPane("text/html", html);
        page.setEditable(false);
        page.setCaretPosition(0);
        JScrollPane scroll = new JScrollPane(page, ScrollPaneConstants.VERTICAL_SCROLLBAR_AS_NEEDED,
                ScrollPaneConstants.HORIZONTAL_SCROLLBAR_NEVER);
        scroll.setPreferredSize(new Dimension(560, 480));
        JButton close = new JButton("Close");
        close.addActionListener(e -> dialog.dispose());
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        buttons.add(close);
        dialog.add(scroll, BorderLayout.CENTER);
        dialog.add(buttons, BorderLayout.SOUTH);
        dialog.getRootPane().setDefaultButton(close);
        EscapeCloses.install(dialog);
        dialog.setDefaultCloseOperation(JDialog.DISPOSE_ON_CLOSE);
        dialog.pack();
        dialog.setLocationRelativeTo(owner);
        dialog.setVisible(true);
    }
}
