package gizmoball.controller;

import gizmoball.boardfile.BoardFileException;
import gizmoball.boardfile.BoardFiles;
import gizmoball.boardfile.FileErrors;
import gizmoball.highscore.HighScore;
import gizmoball.highscore.HighScoreStore;
import gizmoball.highscore.HighScoreTable;
import gizmoball.model.Board;
import gizmoball.model.BoardChange;
import gizmoball.model.game.Notice;
import gizmoball.replay.Replay;
import gizmoball.replay.ReplayFiles;
import gizmoball.session.GameSession;
import gizmoball.session.Mode;
import gizmoball.view.GameOverDialog;
import gizmoball.view.GameWindow;
import gizmoball.view.HighScoresDialog;
import gizmoball.view.ScorePanel;
import java.io.IOException;
import java.nio.file.Path;
import java.text.NumberFormat;
import java.time.Clock;
import java.time.LocalDate;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import javax.swing.JFileChooser;
import javax.swing.SwingUtilities;
import javax.swing.filechooser.FileNameExtensionFilter;

/**
 * The Game menu's games: New game, the game-over dialog and the high-score entry it asks for, the board's table,
 * watching a high score's game or a replay file in the window (the loop plays its keys), and saving the replay of the
 * game on the board. The board as built, which keys the table and starts every replay, is the session's design.
 */
public final class GameCommands {
    /** Shown in the game-over dialog: the shortcut GameWindow gives Game > New game. */
    public static final String NEW_GAME_SHORTCUT = "Ctrl+Shift+N";

    private final GameWindow window;
    private final GameSession session;
    private final GameLoop loop;
    private final Settings settings;
    private final HighScoreStore store;
    private final ScorePanel scorePanel;
    private final Clock clock;
    /** The game over was answered: the dialog shows once a game. */
    private boolean gameOverSeen;
    /** The game's notices already told in the status line. */
    private int noticesTold;
    /** How many players a new game on the board is for (Game > Players). */
    private int players = 1;

    public GameCommands(GameWindow window, GameSession session, GameLoop loop, Settings settings, ScorePanel scorePanel,
                        Clock clock) {
        this.window = window;
        this.session = session;
        this.loop = loop;
        this.settings = settings;
        this.store = settings.highScores();
        this.scorePanel = scorePanel;
        this.clock = clock;
    }

    /** Watches the board for the end of a game and the session for a new board (registered once it is whole). */
    public static GameCommands install(GameWindow window, GameSession session, GameLoop loop, Settings settings,
                                       ScorePanel scorePanel, Clock clock) {
        GameCommands games = new GameCommands(window, session, loop, settings, scorePanel, clock);
        session.board().addObserver((board, change) -> games.boardChanged(change));
        session.addStateListener(games::showBest);
        session.addModeListener(mode -> games.stopWatching());
        games.showBest();
        return games;
    }

    private String asBuilt() {
        return BoardFiles.toText(session.boardToSave());
    }

    private void boardChanged(BoardChange change) {
        Board board = session.board();
        if (change != BoardChange.TICK) {
            // A reset or a load: a new game on the board, for the players chosen.
            gameOverSeen = board.game().isOver();
            noticesTold = board.game().notices().size();
            if (board.ticks() == 0 && board.game().players() != players) {
                board.setPlayers(players);
            }
            return;
        }
        List<Notice> notices = board.game().notices();
        // A nudge's notice comes between ticks, so each is told at the first tick that shows it.
        notices.subList(Math.min(noticesTold, notices.size()), notices.size())
                .forEach(n -> window.statusLine().showMessage(say(n, board.game().players())));
        noticesTold = notices.size();
        if (!gameOverSeen && !loop.isWatching() && board.game().isGame() && board.game().isOver()) {
            gameOverSeen = true;
            // After the tick's own listeners (the views) have seen it, and outside the tick.
            SwingUtilities.invokeLater(this::gameOver);
        }
    }

    /** What the window says of a notice of the game. */
    static String say(Notice notice, int players) {
        String who = "Player " + (notice.player() + 1);
        return switch (notice.kind()) {
            case WARNING -> "Careful: one more nudge tilts!";
            case TILT -> "TILT: flippers and plunger dead until the ball drains";
            case BALL_SAVED -> "Ball saved: launch it again";
            case EXTRA_BALL -> players > 1 ? "Extra ball for " + who + "!" : "Extra ball!";
            case NEXT_PLAYER -> who + ", your ball";
        };
    }

    /** Game > Players: a new game for that many players, who stay chosen for the games after it. */
    public void newGame(int count) {
        players = count;
        newGame();
    }

    /** Game > New game: back to the board as built, in play mode, running. */
    public void newGame() {
        stopWatching();
        if (session.mode() != Mode.PLAY) {
            session.setMode(Mode.PLAY);
        }
        session.reset();
        session.board().setPlayers(players);
        loop.start();
        window.refresh();
        window.statusLine().showMessage(players == 1 ? "New game" : "New game for " + players + " players");
    }

    /** Leaves a replay being watched, if any: the board's next ticks are the player's. */
    public void stopWatching() {
        if (loop.isWatching()) {
            loop.stopWatching();
            loop.stop();
        }
        scorePanel.setNotice("");
    }

    /** The final score of each player in turn, with a name for the table from each whose score ranks on it. */
    private void gameOver() {
        loop.stop();
        Board board = session.board();
        String built = asBuilt();
        HighScoreStore.Loaded loaded = store.load(built);
        loaded.problem().ifPresent(window.statusLine()::showMessage);
        HighScoreTable table = loaded.table();
        int count = board.game().players();
        for (int player = 0; player < count; player++) {
            long score = board.game().score(player);
            String who = count == 1 ? "" : "Player " + (player + 1);
            Optional<String> name = GameOverDialog.show(window, who, score, table.placeOf(score),
                    settings.playerName(), NEW_GAME_SHORTCUT);
            if (name.isPresent()) {
                settings.setPlayerName(name.get());
                HighScore entry = new HighScore(name.get(), score, LocalDate.now(clock),
                        Replay.of(built, board, Board.DEFAULT_TICK));
                table = table.with(entry);
                store.save(built, table).ifPresentOrElse(window.statusLine()::showMessage,
                        () -> window.statusLine().showMessage("High score kept: " + format(score) + ", "
                                + entry.name()));
                showBest();
            }
        }
        window.refresh();
    }

    /** The best of the board as built in the score panel. */
    private void showBest() {
        HighScoreTable table = store.load(asBuilt()).table();
        table.best().ifPresentOrElse(best -> scorePanel.setBest(Optional.of(best.name()), best.score()),
                scorePanel::clearBest);
    }

    /** Game > High scores: the board's table, from which an entry's game can be watched. */
    public void showHighScores() {
        loop.hold();
        HighScoreStore.Loaded loaded = store.load(asBuilt());
        try {
            HighScoresDialog.show(window, session.boardName(), loaded.table(), loaded.problem(),
                    entry -> SwingUtilities.invokeLater(() -> watch(entry.replay(), entry.name() + "'s "
                            + format(entry.score()))),
                    () -> SwingUtilities.invokeLater(this::watchFile));
        } finally {
            loop.release();
        }
    }

    /** Game > Watch a replay file. */
    public void watchFile() {
        JFileChooser chooser = replayChooser();
        if (chooser.showOpenDialog(window) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path file = chooser.getSelectedFile().toPath();
        try {
            Replay replay = ReplayFiles.read(file);
            watch(replay, String.valueOf(file.getFileName()));
        } catch (IOException e) {
            window.statusLine().showMessage(FileErrors.cannotRead(file, e));
        } catch (ReplayFiles.BadReplay e) {
            window.statusLine().showMessage(e.getMessage());
        }
    }

    /**
     * Plays {@code replay} in the window from its board as built, at the loop's speed, the player's keys kept off the
     * board until it ends (or New game, Reset, a mode change).
     */
    public void watch(Replay replay, String what) {
        Board board;
        try {
            board = replay.boardAsBuilt(what);
        } catch (BoardFileException e) {
            window.statusLine().showMessage("The replay's board does not load: " + e.getMessage());
            return;
        }
        if (session.mode() != Mode.PLAY) {
            session.setMode(Mode.PLAY);
        }
        loop.stop();
        session.board().replaceContents(board);
        session.board().setPlayers(replay.players());   // the board's observers set the players chosen here
        gameOverSeen = false;
        scorePanel.setNotice("Watching " + what);
        loop.watch(replay.keys(), replay.ticks(), () -> {
            long reached = session.board().game().score();
            scorePanel.setNotice("Replay over");
            window.statusLine().showMessage("Replay over: " + format(reached) + " points"
                    + (reached == replay.score() ? ", as recorded" : ", not the " + format(replay.score()) + " recorded")
                    + ". " + NEW_GAME_SHORTCUT + " starts a new game.");
            window.refresh();
        });
        loop.start();
        window.refresh();
        window.statusLine().showMessage("Watching " + what + " (" + format(replay.ticks()) + " ticks)");
    }

    /** Game > Save replay: the game on the board so far, from the board as built, as a replay file. */
    public void saveReplay() {
        if (loop.isWatching()) {
            window.statusLine().showMessage("A replay is being watched: it has its file already");
            return;
        }
        Replay replay = Replay.of(asBuilt(), session.board(), Board.DEFAULT_TICK);
        JFileChooser chooser = replayChooser();
        // Named after the board: its file's name (or a sample's, or untitled) without its extension.
        String board = session.file().map(f -> String.valueOf(f.getFileName())).orElse(session.suggestedFileName());
        chooser.setSelectedFile(new java.io.File(board.replaceFirst("\\.[^.]*$", "") + ".replay.json"));
        if (chooser.showSaveDialog(window) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path file = chooser.getSelectedFile().toPath();
        if (!file.getFileName().toString().contains(".")) {
            file = file.resolveSibling(file.getFileName() + ".json");
        }
        try {
            ReplayFiles.write(replay, file);
            window.statusLine().showMessage("Replay saved: " + file.getFileName() + " (" + format(replay.score())
                    + " points, " + format(replay.ticks()) + " ticks)");
        } catch (IOException e) {
            window.statusLine().showMessage(FileErrors.cannotSave(file, e));
        }
    }

    private static JFileChooser replayChooser() {
        JFileChooser chooser = new JFileChooser();
        chooser.setFileFilter(new FileNameExtensionFilter("Gizmoball replays (*.json)", "json"));
        return chooser;
    }

    private static String format(long n) {
        return NumberFormat.getIntegerInstance(Locale.ROOT).format(n);
    }
}
