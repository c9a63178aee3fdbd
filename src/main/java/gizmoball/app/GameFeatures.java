package gizmoball.app;

import gizmoball.controller.GameCommands;
import gizmoball.controller.GameLoop;
import gizmoball.controller.Settings;
import gizmoball.model.game.Game;
import gizmoball.session.GameSession;
import gizmoball.session.Mode;
import gizmoball.view.GameWindow;
import gizmoball.view.LaunchHint;
import gizmoball.view.ScorePanel;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.time.Clock;
import javax.swing.ButtonGroup;
import javax.swing.JMenu;
import javax.swing.JRadioButtonMenuItem;

/**
 * Makes the window a game: the score panel above the board, the launch hint over it, and Game > New game, Players
 * (1 to 4: a new game for that many), High scores, Watch a replay file and Save replay, at the top of the Game menu.
 */
public final class GameFeatures {
    private final GameCommands commands;
    private final ScorePanel scorePanel;
    private final LaunchHint launchHint;

    private GameFeatures(GameCommands commands, ScorePanel scorePanel, LaunchHint launchHint) {
        this.commands = commands;
        this.scorePanel = scorePanel;
        this.launchHint = launchHint;
    }

    public static GameFeatures install(GameWindow window, GameSession session, GameLoop loop, Settings settings) {
        ScorePanel scorePanel = ScorePanel.of(session.board());
        window.setScorePanel(scorePanel);
        LaunchHint hint = new LaunchHint(session.board(), () -> session.mode() == Mode.PLAY && !loop.isWatching());
        window.boardPanel().addOverlay(hint);
        GameCommands commands = GameCommands.install(window, session, loop, settings, scorePanel, Clock.systemDefaultZone());
        JMenu game = PlayFeatures.menu(window.menus(), "Game");
        int at = 0;
        // Ctrl+Shift, like every shortcut a Ctrl one, so no board key is shadowed (Ctrl+N is File > New).
        game.insert(GameWindow.action("New game", KeyEvent.VK_N, InputEvent.SHIFT_DOWN_MASK, commands::newGame), at++);
        JMenu players = new JMenu("Players");
        ButtonGroup group = new ButtonGroup();
        for (int n = 1; n <= Game.MAX_PLAYERS; n++) {
            int count = n;
            JRadioButtonMenuItem item = new JRadioButtonMenuItem(n == 1 ? "1 player" : n + " players", n == 1);
            item.setName("game.players." + n);
            item.addActionListener(e -> commands.newGame(count));
            group.add(item);
            players.add(item);
        }
        game.insert(players, at++);
        game.insert(GameWindow.action("High scores...", KeyEvent.VK_H, InputEvent.SHIFT_DOWN_MASK,
                commands::showHighScores), at++);
        game.insert(GameWindow.action("Watch a replay file...", KeyEvent.VK_W, InputEvent.SHIFT_DOWN_MASK,
                commands::watchFile), at++);
        game.insert(GameWindow.action("Save replay...", KeyEvent.VK_E, InputEvent.SHIFT_DOWN_MASK,
                commands::saveReplay), at++);
        game.insertSeparator(at);
        return new GameFeatures(commands, scorePanel, hint);
    }

    public GameCommands commands() {
        return commands;
    }

    public ScorePanel scorePanel() {
        return scorePanel;
    }

    public LaunchHint launchHint() {
        return launchHint;
    }
}
