package gizmoball.app;

import gizmoball.controller.BoardFileCommands;
import gizmoball.controller.GameCommands;
import gizmoball.controller.GameLoop;
import gizmoball.controller.KeyForwarder;
import gizmoball.controller.ModalPause;
import gizmoball.controller.Settings;
import gizmoball.model.Board;
import gizmoball.session.GameSession;
import gizmoball.session.Mode;
import gizmoball.view.GameWindow;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import javax.swing.SwingUtilities;

/**
 * The composition root: builds the session, the window, the game loop, the file commands, the key forwarding
 * and build mode, and wires them to each other. It is the only class that knows all the layers; the view
 * knows none of the controllers, and the controllers know the view only as the place they report to.
 */
public final class Gizmoball {
    private final GameSession session;
    private final GameLoop loop;
    private final GameWindow window;
    private final BoardFileCommands files;
    private final BuildModeInstaller.BuildMode build;
    private final PlayFeatures play;
    private final GameFeatures game;

    private Gizmoball(GameSession session, GameLoop loop, GameWindow window, BoardFileCommands files,
                      BuildModeInstaller.BuildMode build, PlayFeatures play, GameFeatures game) {
        this.session = session;
        this.loop = loop;
        this.window = window;
        this.files = files;
        this.build = build;
        this.play = play;
        this.game = game;
    }

    /**
     * Opens a window on {@code board}, or on an empty board if it is null (on the event dispatch thread,
     * whichever thread calls this). A board that cannot be loaded is reported once the window shows.
     */
    public static Gizmoball launch(Path board) {
        return launch(board, Settings.forUser());
    }

    /** As {@link #launch(Path)}, with the player's settings kept in {@code settings}. */
    public static Gizmoball launch(Path board, Settings settings) {
        if (!SwingUtilities.isEventDispatchThread()) {
            Gizmoball[] app = new Gizmoball[1];
            try {
                SwingUtilities.invokeAndWait(() -> app[0] = launch(board, settings));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while opening the window", e);
            } catch (InvocationTargetException e) {
                throw new IllegalStateException("could not open the window", e.getCause());
            }
            return app[0];
        }
        Gizmoball app = assemble(settings);
        if (board != null) {
            app.files.openAtLaunch(board);
        }
        app.window.setVisible(true);
        return app;
    }

    private static Gizmoball assemble(Settings settings) {
        GameSession session = new GameSession();
        GameLoop loop = new GameLoop(session.board(), Board.DEFAULT_TICK);
        // The window's menus call the file commands, and the file commands open their dialogs over the
        // window: the commands object is made first and given the file commands once the window exists.
        WindowCommands commands = new WindowCommands(session, loop);
        GameWindow window = GameWindow.create(session, commands);
        BoardFileCommands files = new BoardFileCommands(window, window.statusLine()::showMessage, session, loop);
        commands.attach(window, files);

        // A replay being watched plays its own keys: the player's stay off the board.
        KeyForwarder keys = new KeyForwarder(window, session.board(),
                () -> session.mode() == Mode.PLAY && !loop.isWatching());
        keys.install();
        session.addModeListener(mode -> {
            loop.stop();
            keys.releaseAll();
        });
        loop.addRunningListener(window::refresh);
        loop.addFrameListener(window.boardPanel()::setTickFraction);
        loop.setFailureHandler(e -> {
            e.printStackTrace();
            window.statusLine().showMessage("Simulation stopped by an internal error: " + e);
        });
        window.addWindowListener(new WindowAdapter() {
            /** However the window goes (Quit, or disposed by a test), the loop and the key hook go with it. */
            @Override
            public void windowClosed(WindowEvent e) {
                loop.stop();
                keys.uninstall();
            }
        });
        ModalPause.install(window, loop);
        BuildModeInstaller.BuildMode build = BuildModeInstaller.install(window, session);
        PlayFeatures play = PlayFeatures.install(window, session, loop, files, build.controller(), settings);
        GameFeatures game = GameFeatures.install(window, session, loop, settings);
        commands.attachGames(game.commands());
        return new Gizmoball(session, loop, window, files, build, play, game);
    }

    public GameWindow window() {
        return window;
    }

    public GameSession session() {
        return session;
    }

    public GameLoop loop() {
        return loop;
    }

    public BoardFileCommands files() {
        return files;
    }

    public BuildModeInstaller.BuildMode build() {
        return build;
    }

    public PlayFeatures playFeatures() {
        return play;
    }

    public GameFeatures gameFeatures() {
        return game;
    }

    /** The menus' commands: the game loop, the session and the file commands. */
    private static final class WindowCommands implements GameWindow.Commands {
        private final GameSession session;
        private final GameLoop loop;
        private GameWindow window;
        private BoardFileCommands files;
        private GameCommands games;

        WindowCommands(GameSession session, GameLoop loop) {
            this.session = session;
            this.loop = loop;
        }

        void attach(GameWindow window, BoardFileCommands files) {
            this.window = window;
            this.files = files;
        }

        void attachGames(GameCommands games) {
            this.games = games;
        }

        @Override
        public void newBoard() {
            files.newBoard();
        }

        @Override
        public void open() {
            files.open();
        }

        @Override
        public void save() {
            files.save();
        }

        @Override
        public void saveAs() {
            files.saveAs();
        }

        @Override
        public void reload() {
            files.reload();
        }

        @Override
        public void quit() {
            if (files.confirmDiscard("quit")) {
                window.dispose();
            }
        }

        @Override
        public void start() {
            loop.start();
        }

        @Override
        public void stop() {
            loop.stop();
        }

        @Override
        public void tick() {
            loop.step();
        }

        @Override
        public void reset() {
            games.stopWatching();
            session.reset();
            window.refreshStatus();
            window.statusLine().showMessage("Reset: the board is back as loaded or built");
        }

        @Override
        public void setMode(Mode mode) {
            session.setMode(mode);
        }

        @Override
        public void openSample(String name) {
            files.openSample(name);
        }

        @Override
        public boolean running() {
            return loop.isRunning();
        }

        @Override
        public String speed() {
            return loop.speed().label();
        }
    }
}
