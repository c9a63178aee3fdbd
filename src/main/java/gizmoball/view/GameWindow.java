package gizmoball.view;

import gizmoball.controller.GameLoop;
import gizmoball.controller.GameSession;
import gizmoball.controller.KeyForwarder;
import gizmoball.controller.Mode;
import gizmoball.model.Board;
import java.awt.BorderLayout;
import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import java.util.List;
import javax.swing.AbstractAction;
import javax.swing.AbstractButton;
import javax.swing.Action;
import javax.swing.ButtonGroup;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.JToggleButton;
import javax.swing.JToolBar;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.Timer;

/**
 * The game's window: board view, menus, toolbar and status line around one {@link GameSession}.
 * Every shortcut uses Ctrl, so no board key binding (plain keys) is shadowed by a menu.
 */
public final class GameWindow extends JFrame {
    private static final int STATUS_REFRESH_MILLIS = 200;

    private final GameSession session = new GameSession();
    private final BoardPanel boardPanel = new BoardPanel(session.board());
    private final StatusLine statusLine = new StatusLine();
    private final GameLoop loop = new GameLoop(session.board(), Board.DEFAULT_TICK);
    private final BoardFileCommands files = new BoardFileCommands(this, session, loop);
    private final KeyForwarder keys = new KeyForwarder(this, session.board(), () -> session.mode() == Mode.PLAY);
    private final Timer statusRefresh = new Timer(STATUS_REFRESH_MILLIS, e -> refreshStatus());
    private final JPanel centre = new JPanel(new BorderLayout());
    private final JMenuBar menus = new JMenuBar();
    private final JToolBar toolBar = new JToolBar();
    private JComponent west;
    private JComponent east;

    private final Action newBoard = action("New", KeyEvent.VK_N, 0, files::newBoard);
    private final Action open = action("Open...", KeyEvent.VK_O, 0, files::open);
    private final Action save = action("Save", KeyEvent.VK_S, 0, files::save);
    private final Action saveAs = action("Save As...", KeyEvent.VK_S, InputEvent.SHIFT_DOWN_MASK, files::saveAs);
    private final Action reload = action("Reload", KeyEvent.VK_R, 0, files::reload);
    private final Action quit = action("Quit", KeyEvent.VK_Q, 0, this::quit);
    private final Action start = action("Start", KeyEvent.VK_G, 0, loop::start);
    private final Action stop = action("Stop", KeyEvent.VK_H, 0, loop::stop);
    private final Action tick = action("Tick", KeyEvent.VK_T, 0, loop::step);
    private final Action reset = action("Reset", KeyEvent.VK_R, InputEvent.SHIFT_DOWN_MASK, this::reset);
    private final Action play = action("Play", KeyEvent.VK_P, 0, () -> session.setMode(Mode.PLAY));
    private final Action build = action("Build", KeyEvent.VK_B, 0, () -> session.setMode(Mode.BUILD));
    private final Action keysHelp = action("Keys of this board...", KeyEvent.VK_K, 0, this::showKeys);
    private final Action howToPlay = command(HelpPages.HOW_TO_PLAY + "...",
            () -> HelpPages.show(this, HelpPages.HOW_TO_PLAY, HelpPages.howToPlay(menus, session.board())));
    private final Action buildModeHelp = command(HelpPages.BUILD_MODE + "...",
            () -> HelpPages.show(this, HelpPages.BUILD_MODE, HelpPages.buildMode()));

    private GameWindow() {
        super("Gizmoball");
        setDefaultCloseOperation(DO_NOTHING_ON_CLOSE);
        addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                quit();
            }

            @Override
            public void windowOpened(WindowEvent e) {
                boardPanel.requestFocusInWindow();
            }

            /** However the window goes (Quit, or disposed by a test), its timers and key hook go with it. */
            @Override
            public void windowClosed(WindowEvent e) {
                loop.stop();
                statusRefresh.stop();
                keys.uninstall();
            }
        });
        buildMenus();
        buildToolBar();
        centre.add(boardPanel, BorderLayout.CENTER);
        add(toolBar, BorderLayout.NORTH);
        add(centre, BorderLayout.CENTER);
        add(statusLine, BorderLayout.SOUTH);

        session.addModeListener(this::modeChanged);
        session.addStateListener(this::refreshControls);
        loop.addRunningListener(this::refreshControls);
        loop.setFailureHandler(e -> {
            e.printStackTrace();
            statusLine.showMessage("Simulation stopped by an internal error: " + e);
        });
        keys.install();
        statusRefresh.start();
        refreshControls();
        ModalPause.install(this, loop);
        pack();
        // Centred on the screen; the window's remembered place, if any, is restored over this.
        setLocationRelativeTo(null);
    }

    /**
     * Opens a window on {@code board}, or on an empty board if it is null (on the event dispatch thread,
     * whichever thread calls this). A board that cannot be loaded is reported once the window shows.
     */
    public static GameWindow launch(Path board) {
        if (SwingUtilities.isEventDispatchThread()) {
            GameWindow window = new GameWindow();
            if (board != null) {
                window.files.openAtLaunch(board);
            }
            window.setVisible(true);
            return window;
        }
        GameWindow[] window = new GameWindow[1];
        try {
            SwingUtilities.invokeAndWait(() -> window[0] = launch(board));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while opening the window", e);
        } catch (InvocationTargetException e) {
            throw new IllegalStateException("could not open the window", e.getCause());
        }
        return window[0];
    }

    public BoardPanel boardPanel() {
        return boardPanel;
    }

    public JMenuBar menus() {
        return menus;
    }

    public JToolBar toolBar() {
        return toolBar;
    }

    public GameSession session() {
        return session;
    }

    public GameLoop loop() {
        return loop;
    }

    public StatusLine statusLine() {
        return statusLine;
    }

    /** The File menu's commands (package-private: the tests open files without a file chooser). */
    BoardFileCommands fileCommands() {
        return files;
    }

    /** The build-mode side panels; shown while the session is in BUILD mode. Either may be null. */
    public void setSidePanels(JComponent west, JComponent east) {
        if (this.west != null) {
            centre.remove(this.west);
        }
        if (this.east != null) {
            centre.remove(this.east);
        }
        this.west = west;
        this.east = east;
        if (west != null) {
            centre.add(west, BorderLayout.WEST);
        }
        if (east != null) {
            centre.add(east, BorderLayout.EAST);
        }
        showSidePanels(session.mode() == Mode.BUILD);
    }

    private void buildMenus() {
        JMenu file = new JMenu("File");
        file.setMnemonic(KeyEvent.VK_F);
        for (Action a : new Action[] {newBoard, open, save, saveAs, reload}) {
            file.add(a);
        }
        file.addSeparator();
        file.add(quit);
        JMenu game = new JMenu("Game");
        game.setMnemonic(KeyEvent.VK_G);
        for (Action a : new Action[] {start, stop, tick, reset}) {
            game.add(a);
        }
        JMenu mode = new JMenu("Mode");
        mode.setMnemonic(KeyEvent.VK_M);
        ButtonGroup modes = new ButtonGroup();
        for (Action a : new Action[] {play, build}) {
            JMenuItem item = new JRadioButtonMenuItem(a);
            modes.add(item);
            mode.add(item);
        }
        JMenu help = new JMenu("Help");
        help.setMnemonic(KeyEvent.VK_H);
        help.add(howToPlay);
        help.add(buildModeHelp);
        help.add(keysHelp);
        menus.add(file);
        menus.add(game);
        menus.add(mode);
        menus.add(help);
        setJMenuBar(menus);
    }

    private void buildToolBar() {
        toolBar.setFloatable(false);
        for (Action a : new Action[] {open, save, reload}) {
            toolBar.add(button(new JButton(a)));
        }
        toolBar.addSeparator();
        for (Action a : new Action[] {start, stop, tick, reset}) {
            toolBar.add(button(new JButton(a)));
        }
        toolBar.addSeparator();
        ButtonGroup modes = new ButtonGroup();
        for (Action a : new Action[] {play, build}) {
            JToggleButton toggle = new JToggleButton(a);
            modes.add(toggle);
            toolBar.add(button(toggle));
        }
    }

    /** Toolbar buttons never take the focus: a focused button would swallow Space, a common board key. */
    private static AbstractButton button(AbstractButton b) {
        b.setFocusable(false);
        b.setName("toolbar." + b.getText());
        return b;
    }

    static Action action(String name, int key, int extraModifiers, Runnable body) {
        Action a = command(name, body);
        a.putValue(Action.ACCELERATOR_KEY, KeyStroke.getKeyStroke(key, InputEvent.CTRL_DOWN_MASK | extraModifiers));
        return a;
    }

    /** A menu command without a shortcut. */
    private static Action command(String name, Runnable body) {
        return new AbstractAction(name) {
            @Override
            public void actionPerformed(ActionEvent e) {
                body.run();
            }
        };
    }

    private void modeChanged(Mode mode) {
        loop.stop();
        keys.releaseAll();
        boardPanel.setGridVisible(mode == Mode.BUILD);
        showSidePanels(mode == Mode.BUILD);
        statusLine.showMessage(mode == Mode.PLAY ? "Play mode" : "Build mode");
    }

    private void showSidePanels(boolean visible) {
        if (west != null) {
            west.setVisible(visible);
        }
        if (east != null) {
            east.setVisible(visible);
        }
        centre.revalidate();
        centre.repaint();
    }

    private void refreshControls() {
        boolean playing = session.mode() == Mode.PLAY;
        boolean running = loop.isRunning();
        start.setEnabled(playing && !running);
        stop.setEnabled(running);
        tick.setEnabled(playing && !running);
        reset.setEnabled(playing);
        reload.setEnabled(session.file().isPresent());
        play.putValue(Action.SELECTED_KEY, playing);
        build.putValue(Action.SELECTED_KEY, !playing);
        setTitle("Gizmoball - " + session.boardName() + (session.isModified() ? " *" : ""));
        refreshStatus();
    }

    /** Brings the status line up to date now (the window also does so a few times a second). */
    public void refreshStatus() {
        statusLine.show(session.boardName(), session.mode() == Mode.PLAY ? "Play" : "Build", loop.isRunning(),
                loop.speed().label(), session.board().time(), boardPanel.framesPerSecond());
    }

    private void reset() {
        session.reset();
        statusLine.showMessage("Reset: the board is back as loaded or built");
        refreshStatus();
    }

    private void showKeys() {
        List<String> lines = KeyHelp.describe(session.board());
        JOptionPane.showMessageDialog(this, lines.isEmpty() ? "This board binds no keys." : String.join("\n", lines),
                "Keys of " + session.boardName(), JOptionPane.INFORMATION_MESSAGE);
    }

    private void quit() {
        if (files.confirmDiscard("quit")) {
            dispose();
        }
    }
}
