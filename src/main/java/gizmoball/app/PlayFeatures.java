package gizmoball.app;

import gizmoball.controller.BoardFileCommands;
import gizmoball.controller.GameLoop;
import gizmoball.controller.Settings;
import gizmoball.controller.Speed;
import gizmoball.editor.Editor;
import gizmoball.preview.AimPreview;
import gizmoball.preview.Predictor;
import gizmoball.session.GameSession;
import gizmoball.session.Mode;
import gizmoball.sound.GameSounds;
import gizmoball.sound.SoundPlayer;
import gizmoball.view.BallTrails;
import gizmoball.view.GameWindow;
import gizmoball.view.PhysicsOverlay;
import gizmoball.view.editor.AimPreviewOverlay;
import java.awt.GraphicsConfiguration;
import java.awt.GraphicsDevice;
import java.awt.GraphicsEnvironment;
import java.awt.Rectangle;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import javax.swing.Action;
import javax.swing.ButtonGroup;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;

/**
 * Adds to a game window what makes the physics visible and audible and the window remember itself:
 * Game > Speed and Sound, View > Ball trails, Physics overlay and Aim preview, and the settings that stick
 * (speed, sound, trails, overlay, aim preview, last folder, window place and size).
 * Every setting the player changes is written to {@link Settings} at once.
 */
public final class PlayFeatures {
    private final GameWindow window;
    private final GameSession session;
    private final GameLoop loop;
    private final BoardFileCommands files;
    private final Settings settings;
    private final BallTrails trails;
    private final SoundPlayer sound;
    private JCheckBoxMenuItem soundItem;
    private final AimPreview aim;
    private final PhysicsOverlay overlay;

    private PlayFeatures(GameWindow window, GameSession session, GameLoop loop, BoardFileCommands files,
                         Editor editor, Settings settings) {
        this.window = window;
        this.session = session;
        this.loop = loop;
        this.files = files;
        this.settings = settings;
        this.trails = new BallTrails(session.board());
        this.sound = new SoundPlayer(notice -> SwingUtilities.invokeLater(() -> soundLost(notice)));
        this.aim = new AimPreview(session.board(),
                () -> new AimPreview.Inputs(editor.tool(), editor.preview(), editor.selected()), new Predictor(),
                SwingUtilities::invokeLater);
        editor.addStateListener(aim::refresh);
        this.overlay = PhysicsOverlay.of(session.board());
    }

    public static PlayFeatures install(GameWindow window, GameSession session, GameLoop loop,
                                       BoardFileCommands files, Editor editor, Settings settings) {
        PlayFeatures features = new PlayFeatures(window, session, loop, files, editor, settings);
        features.installSpeed();
        features.installSound();
        features.installView();
        features.rememberFolder();
        features.rememberRecentFiles();
        features.hintOnFirstRun();
        features.rememberPlace();
        features.tellWhereSettingsAreKept();
        return features;
    }

    /** Help > How to play says where the settings and high scores are, and how to keep them elsewhere. */
    private void tellWhereSettingsAreKept() {
        window.tellWhereSettingsAreKept(settings.whereKept().map(folder -> "They are kept in " + folder
                + " (under your account's home, whatever HOME says). To keep them in another folder, start the"
                + " game with -D" + Settings.PREFS_ROOT + "=FOLDER (for instance in JDK_JAVA_OPTIONS), and move"
                + " .java/.userPrefs there to take them along.")
                .orElse("They are kept in Java's preferences of your account (on Windows in the registry, under"
                        + " HKEY_CURRENT_USER\\Software\\JavaSoft\\Prefs)."));
    }

    public BallTrails trails() {
        return trails;
    }

    public AimPreview aimPreview() {
        return aim;
    }

    public PhysicsOverlay physicsOverlay() {
        return overlay;
    }

    private void installSpeed() {
        JMenu speedMenu = new JMenu("Speed");
        ButtonGroup group = new ButtonGroup();
        Speed[] speeds = Speed.values();
        for (int i = 0; i < speeds.length; i++) {
            Speed speed = speeds[i];
            // Ctrl+1 (slowest) to Ctrl+5 (fastest): Ctrl, like every shortcut, so no board key is shadowed.
            Action a = GameWindow.action(speed.label(), KeyEvent.VK_1 + i, 0, () -> setSpeed(speed));
            a.putValue(Action.SELECTED_KEY, speed == settings.speed());
            JRadioButtonMenuItem item = new JRadioButtonMenuItem(a);
            group.add(item);
            speedMenu.add(item);
        }
        loop.setSpeed(settings.speed());
        JMenu game = menu(window.menus(), "Game");
        game.addSeparator();
        game.add(speedMenu);
        window.refreshStatus();
    }

    private void setSpeed(Speed speed) {
        loop.setSpeed(speed);
        settings.setSpeed(speed);
        window.refreshStatus();
        window.statusLine().showMessage("Speed " + speed.label());
    }

    public SoundPlayer sound() {
        return sound;
    }

    private void installSound() {
        JMenu game = menu(window.menus(), "Game");
        // Ctrl+M (mute), like every shortcut a Ctrl one, so no board key is shadowed.
        soundItem = toggle("Sound", KeyEvent.VK_M, 0, settings.sound(), on -> {
            if (!sound.hasDevice()) {
                soundLost(SoundPlayer.NO_DEVICE);
                return;
            }
            sound.setEnabled(on);
            settings.setSound(on);
            window.statusLine().showMessage(on ? "Sound on" : "Sound off");
        });
        game.add(soundItem);
        sound.setEnabled(settings.sound());
        GameSounds.attach(session.board(), sound);
        window.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                sound.close();
            }
        });
    }

    /**
     * Without a device sound is off, and everything says so: the menu item is unticked (with the reason as its
     * tooltip) and Ctrl+M repeats the reason instead of claiming sound on. The player's setting is kept for a
     * run with a device.
     */
    private void soundLost(String notice) {
        soundItem.setSelected(false);
        soundItem.setToolTipText(notice);
        window.statusLine().showMessage(notice);
    }

    private void installView() {
        JMenu view = new JMenu("View");
        view.setMnemonic(KeyEvent.VK_V);
        view.add(toggle("Ball trails", KeyEvent.VK_T, InputEvent.SHIFT_DOWN_MASK, settings.ballTrails(), on -> {
            trails.setEnabled(on);
            settings.setBallTrails(on);
            window.boardPanel().repaint();
        }));
        trails.setEnabled(settings.ballTrails());
        window.boardPanel().addUnderlay(trails);
        loop.addRunningListener(() -> {
            if (!loop.isRunning()) {
                trails.clear();
                window.boardPanel().repaint();
            }
        });
        view.add(toggle("Physics overlay", KeyEvent.VK_O, InputEvent.SHIFT_DOWN_MASK, settings.physicsOverlay(), on -> {
            settings.setPhysicsOverlay(on);
            overlayShown();
        }));
        overlayShown();
        session.addModeListener(mode -> overlayShown());
        window.boardPanel().addOverlay(overlay);
        view.add(toggle("Aim preview", KeyEvent.VK_A, InputEvent.SHIFT_DOWN_MASK, settings.aimPreview(), on -> {
            settings.setAimPreview(on);
            aimPreviewShown();
        }));
        aimPreviewShown();
        session.addModeListener(mode -> aimPreviewShown());
        aim.addListener(window.boardPanel()::repaint);
        window.boardPanel().addOverlay(new AimPreviewOverlay(aim::current));
        view.addSeparator();
        view.add(command("Zoom in", KeyEvent.VK_EQUALS, () -> window.zoom().zoom(1)));
        view.add(command("Zoom out", KeyEvent.VK_MINUS, () -> window.zoom().zoom(-1)));
        view.add(command("Zoom to fit", KeyEvent.VK_0, window.zoom()::fit));
        JMenuBar menus = window.menus();
        menus.add(view, Math.min(menus.getComponentIndex(menu(menus, "Mode")) + 1, menus.getMenuCount()));
        menus.revalidate();
    }

    /** Play mode only: in build mode nothing ticks, so there is no tick to report. */
    private void overlayShown() {
        overlay.setEnabled(settings.physicsOverlay() && session.mode() == Mode.PLAY);
        window.boardPanel().repaint();
    }

    /** Build mode only: the path of the ball the player is placing, moving or has selected. */
    private void aimPreviewShown() {
        aim.setEnabled(settings.aimPreview() && session.mode() == Mode.BUILD);
    }

    /** An item with a Ctrl shortcut (Ctrl+wheel over the board zooms too). */
    private static JMenuItem command(String name, int key, Runnable action) {
        JMenuItem item = new JMenuItem(name);
        item.setName("view." + name.replace(" ", "").toLowerCase(Locale.ROOT));
        item.setAccelerator(KeyStroke.getKeyStroke(key, InputEvent.CTRL_DOWN_MASK));
        item.addActionListener(e -> action.run());
        return item;
    }

    /** A check box item with a Ctrl shortcut. */
    private static JCheckBoxMenuItem toggle(String name, int key, int extraModifiers, boolean initially,
                                            Consumer<Boolean> changed) {
        JCheckBoxMenuItem item = new JCheckBoxMenuItem(name, initially);
        item.setAccelerator(KeyStroke.getKeyStroke(key, InputEvent.CTRL_DOWN_MASK | extraModifiers));
        item.addActionListener(e -> changed.accept(item.isSelected()));
        return item;
    }

    /**
     * The file chooser starts where the player last chose a board to open or save, in this run or an earlier one
     * (the board opened at launch is no choice of the player's).
     */
    private void rememberFolder() {
        settings.lastFolder().ifPresent(files::startIn);
        files.addFolderListener(this::folderUsed);
    }

    private void folderUsed(Path folder) {
        if (!settings.lastFolder().map(folder::equals).orElse(false)) {
            settings.setLastFolder(folder);
        }
    }

    /** The first run says how to start and which keys play the board, after the launch's own messages. */
    private void hintOnFirstRun() {
        if (!settings.firstRunHintShown()) {
            settings.setFirstRunHintShown();
            SwingUtilities.invokeLater(window::showFirstRunHint);
        }
    }

    /** File > Open recent: the boards last opened or saved, newest first, remembered between runs. */
    private void rememberRecentFiles() {
        JMenu file = menu(window.menus(), "File");
        JMenu recent = new JMenu("Open recent");
        recent.setName("file.recent");
        file.insert(recent, 2);
        Runnable list = () -> {
            recent.removeAll();
            List<Path> paths = settings.recentFiles();
            for (int i = 0; i < paths.size(); i++) {
                Path path = paths.get(i);
                JMenuItem item = new JMenuItem((i + 1) + "  " + path.getFileName() + "   " + path.getParent());
                item.setToolTipText(path.toString());
                item.addActionListener(e -> files.openRecent(path));
                recent.add(item);
            }
            recent.setEnabled(!paths.isEmpty());
        };
        files.addFileListener(path -> {
            settings.addRecentFile(path);
            list.run();
        });
        list.run();
    }

    /**
     * The window opens where it was closed, at the same size, if that place is still on a screen. Kept however the
     * window closes: by its title bar, File > Quit or Ctrl+Q (which dispose it without a closing event).
     */
    private void rememberPlace() {
        settings.windowBounds().filter(PlayFeatures::onSomeScreen).ifPresent(window::setBounds);
        window.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                settings.setWindowBounds(window.getBounds());
            }
        });
    }

    /** True when the window's title bar would be on a screen: at least 100 x 40 pixels of its top. */
    private static boolean onSomeScreen(Rectangle bounds) {
        Rectangle top = new Rectangle(bounds.x, bounds.y, bounds.width, Math.min(bounds.height, 40));
        for (GraphicsDevice device : GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices()) {
            GraphicsConfiguration config = device.getDefaultConfiguration();
            Rectangle visible = config.getBounds().intersection(top);
            if (visible.width >= Math.min(100, bounds.width) && visible.height >= Math.min(40, bounds.height)) {
                return true;
            }
        }
        return false;
    }

    static JMenu menu(JMenuBar menus, String text) {
        for (int i = 0; i < menus.getMenuCount(); i++) {
            if (text.equals(menus.getMenu(i).getText())) {
                return menus.getMenu(i);
            }
        }
        throw new IllegalStateException("the window has no " + text + " menu");
    }
}
