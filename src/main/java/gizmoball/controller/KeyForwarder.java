package gizmoball.controller;

import gizmoball.model.Board;
import java.awt.KeyEventDispatcher;
import java.awt.KeyboardFocusManager;
import java.awt.Window;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.function.BooleanSupplier;
import javax.swing.SwingUtilities;
import javax.swing.Timer;

/**
 * Sends the keys pressed and released while the window has focus to the board's key bindings, whatever
 * component inside the window has the focus. Auto-repeat is filtered out ({@link KeyRepeatFilter}), and
 * keys still held when the window loses focus are released, so no flipper stays up for ever.
 * Presses with Ctrl, Alt or Meta are menu shortcuts and are not sent to the board.
 */
public final class KeyForwarder {
    /** Long enough for an X11 auto-repeat press to follow its release, short enough not to be felt. */
    private static final long PAIR_WINDOW_MILLIS = 20;
    private static final int SHORTCUT_MODIFIERS =
            KeyEvent.CTRL_DOWN_MASK | KeyEvent.ALT_DOWN_MASK | KeyEvent.META_DOWN_MASK;

    private final Window window;
    private final BooleanSupplier active;
    private final KeyRepeatFilter filter;
    private final Timer flushTimer;
    private final KeyEventDispatcher dispatcher = this::dispatch;

    /** Forwards to {@code board} while {@code active} says so (play mode); in between, held keys are released. */
    public KeyForwarder(Window window, Board board, BooleanSupplier active) {
        this.window = window;
        this.active = active;
        this.filter = new KeyRepeatFilter(new KeyRepeatFilter.Edges() {
            @Override
            public void down(int keyCode) {
                board.keyDown(keyCode);
            }

            @Override
            public void up(int keyCode) {
                board.keyUp(keyCode);
            }
        }, PAIR_WINDOW_MILLIS);
        this.flushTimer = new Timer((int) PAIR_WINDOW_MILLIS / 2, e -> flush());
        flushTimer.setRepeats(true);
    }

    public void install() {
        KeyboardFocusManager.getCurrentKeyboardFocusManager().addKeyEventDispatcher(dispatcher);
        window.addWindowFocusListener(new WindowAdapter() {
            @Override
            public void windowLostFocus(WindowEvent e) {
                releaseAll();
            }
        });
    }

    public void uninstall() {
        KeyboardFocusManager.getCurrentKeyboardFocusManager().removeKeyEventDispatcher(dispatcher);
        releaseAll();
    }

    /** Releases every held key (focus lost, mode changed). */
    public void releaseAll() {
        flushTimer.stop();
        filter.releaseAll();
    }

    private boolean dispatch(KeyEvent e) {
        if (!active.getAsBoolean() || SwingUtilities.getWindowAncestor(e.getComponent()) != window
                && e.getComponent() != window) {
            return false;
        }
        if (e.getID() == KeyEvent.KEY_PRESSED && (e.getModifiersEx() & SHORTCUT_MODIFIERS) == 0) {
            filter.pressed(e.getKeyCode());
        } else if (e.getID() == KeyEvent.KEY_RELEASED) {
            filter.released(e.getKeyCode(), nowMillis());
            flushTimer.start();
        }
        return false;
    }

    private static long nowMillis() {
        return System.nanoTime() / 1_000_000;
    }

    private void flush() {
        filter.flush(nowMillis());
        if (!filter.hasPendingReleases()) {
            flushTimer.stop();
        }
    }
}
