package gizmoball.view;

import gizmoball.boardfile.SampleBoards;
import gizmoball.session.GameSession;
import gizmoball.session.Mode;
import java.awt.BorderLayout;
import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
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
import javax.swing.Timer;

/**
 * The game's window: board view, menus, toolbar and status line around one {@link GameSession}.
 * Every shortcut uses Ctrl, so no board key binding (plain keys) is shadowed by a menu. What the menus do is
 * given by the application ({@link Commands}, see gizmoball.app): the window only shows and asks.
 */
public final class GameWindow extends JFrame {
    private static final int STATUS_REFRESH_MILLIS = 200;

    /** What the menus and the toolbar do, and the one piece of state they show that the session does not hold. */
    public interface Commands {
        void newBoard();

        void open();

        void save();

        void saveAs();

        void reload();

        void quit();

        void start();

        void stop();

        void tick();

        void reset();

        void setMode(Mode mode);

        /** Opens a sample board inside the game (File > Sample boards). */
        void openSample(String name);

        boolean running();

        /** The game's speed as the status line shows it ("1x"). */
        String speed();
    }

    private final GameSession session;
    private final Commands commands;
    private final BoardPanel boardPanel;
    private final BoardZoom zoom;
    private final StatusLine statusLine = new StatusLine();
    /** Where the player's settings are kept, as How to play says it (empty: not said). */
    private String settingsPlace = "";
    /** The first-run hint while the status line shows it: starting the game takes it away. */
    private String firstRunHint;
    private final Timer statusRefresh = new Timer(STATUS_REFRESH_MILLIS, e -> refreshStatus());
    private final JPanel centre = new JPanel(new BorderLayout());
    private final JMenuBar menus = new JMenuBar();
    private final JToolBar toolBar = new JToolBar();
    private JComponent west;
    private JComponent east;

    private final Action newBoard;
    private final Action open;
    private final Action save;
    private final Action saveAs;
    private final Action reload;
    private final Action quit;
    private final Action start;
    private final Action stop;
    private final Action tick;
    private final Action reset;
    private final Action play;
    private final Action build;
    private final Action keysHelp;
    private final Action howToPlay;
    private final Action buildModeHelp;

    private GameWindow(GameSession session, Commands commands) {
        super("Gizmoball");
        this.session = session;
        this.commands = commands;
        boardPanel = BoardPanel.of(session.board());
        zoom = BoardZoom.of(boardPanel);
        newBoard = action("New", KeyEvent.VK_N, 0, commands::newBoard);
        open = action("Open...", KeyEvent.VK_O, 0, commands::open);
        save = action("Save", KeyEvent.VK_S, 0, commands::save);
        saveAs = action("Save As...", KeyEvent.VK_S, InputEvent.SHIFT_DOWN_MASK, commands::saveAs);
        reload = action("Reload", KeyEvent.VK_R, 0, commands::reload);
        quit = action("Quit", KeyEvent.VK_Q, 0, commands::quit);
        start = action("Start", KeyEvent.VK_G, 0, commands::start);
        stop = action("Stop", KeyEvent.VK_H, 0, commands::stop);
        tick = action("Tick", KeyEvent.VK_T, 0, commands::tick);
        reset = action("Reset", KeyEvent.VK_R, InputEvent.SHIFT_DOWN_MASK, commands::reset);
        play = action("Play", KeyEvent.VK_P, 0, () -> commands.setMode(Mode.PLAY));
        build = action("Build", KeyEvent.VK_B, 0, () -> commands.setMode(Mode.BUILD));
        keysHelp = action("Keys of this board...", KeyEvent.VK_K, 0, this::showKeys);
        howToPlay = command(HelpPages.HOW_TO_PLAY + "...",
                () -> HelpPages.show(this, HelpPages.HOW_TO_PLAY, HelpPages.howToPlay(menus, session.board(),
                        settingsPlace)));
        buildModeHelp = command(HelpPages.BUILD_MODE + "...",
                () -> HelpPages.show(this, HelpPages.BUILD_MODE, HelpPages.buildMode()));
        setDefaultCloseOperation(DO_NOTHING_ON_CLOSE);
        buildMenus();
        buildToolBar();
        centre.add(zoom.component(), BorderLayout.CENTER);
        add(toolBar, BorderLayout.NORTH);
        add(centre, BorderLayout.CENTER);
        add(statusLine, BorderLayout.SOUTH);
        setIconImages(AppIcon.windowImages());
        pack();
        // Centred on the screen; the window's remembered place, if any, is restored over this.
        setLocationRelativeTo(null);
    }

    /**
     * A window on {@code session}, not shown yet, whose menus do {@code commands}. Listeners are registered
     * here, after construction, so that no half-built window is ever handed to them.
     */
    public static GameWindow create(GameSession session, Commands commands) {
        GameWindow window = new GameWindow(session, commands);
        window.listen();
        return window;
    }

    private void listen() {
        addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                commands.quit();
            }

            @Override
            public void windowOpened(WindowEvent e) {
                boardPanel.requestFocusInWindow();
            }

            /** However the window goes (Quit, or disposed by a test), its timer goes with it. */
            @Override
            public void windowClosed(WindowEvent e) {
                statusRefresh.stop();
            }
        });
        session.addModeListener(this::modeChanged);
        session.addStateListener(this::refreshControls);
        statusRefresh.start();
        refreshControls();
    }

    /** Something the session does not announce changed (the loop started or stopped, a reset): show it. */
    public void refresh() {
        refreshControls();
    }

    /**
     * The hint for a player new to the game, in the status line: how to start, which keys play this board (as many
     * as the line has room for). It goes once the game starts: the board then says what it needs.
     */
    public void showFirstRunHint() {
        firstRunHint = KeyHelp.firstRunHint(session.board(), statusLine::fitsWhole);
        statusLine.showMessage(firstRunHint);
    }

    /** How to play says this of where the settings and high scores are kept. */
    public void tellWhereSettingsAreKept(String place) {
        settingsPlace = place;
    }

    public BoardPanel boardPanel() {
        return boardPanel;
    }

    /** The board view's zoom (View menu, Ctrl+wheel). */
    public BoardZoom zoom() {
        return zoom;
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

    public StatusLine statusLine() {
        return statusLine;
    }

    /** The strip above the board that shows the game (score, balls, best). */
    public void setScorePanel(JComponent panel) {
        centre.add(panel, BorderLayout.NORTH);
        centre.revalidate();
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
        file.add(samplesMenu());
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
        help.add(keysHelp);
        help.add(howToPlay);
        help.add(buildModeHelp);
        menus.add(file);
        menus.add(game);
        menus.add(mode);
        menus.add(help);
        setJMenuBar(menus);
    }

    /** File > Sample boards: the boards that ship inside the game, for a player with no boards/ folder near. */
    private JMenu samplesMenu() {
        JMenu samples = new JMenu("Sample boards");
        for (String name : SampleBoards.names()) {
            samples.add(command(name, () -> commands.openSample(name)));
        }
        samples.setEnabled(samples.getItemCount() > 0);
        return samples;
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

    /** A menu command with the shortcut Ctrl (+ {@code extraModifiers}) + {@code key}. */
    public static Action action(String name, int key, int extraModifiers, Runnable body) {
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
        boolean running = commands.running();
        if (running && statusLine.message().equals(firstRunHint)) {
            statusLine.showMessage("");
        }
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
        statusLine.show(session.boardName(), session.mode() == Mode.PLAY ? "Play" : "Build", commands.running(),
                commands.speed(), session.board().time(), boardPanel.framesPerSecond());
    }

    private void showKeys() {
        List<String> lines = KeyHelp.describe(session.board());
        JOptionPane.showMessageDialog(this, lines.isEmpty() ? "This board binds no keys." : String.join("\n", lines),
                "Keys of " + session.boardName(), JOptionPane.INFORMATION_MESSAGE);
    }
}
