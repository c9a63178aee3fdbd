package gizmoball.controller;

import java.awt.AWTEvent;
import java.awt.Dialog;
import java.awt.Toolkit;
import java.awt.Window;
import java.awt.event.AWTEventListener;
import java.awt.event.ComponentEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.HashSet;
import java.util.Set;

/**
 * Keeps the game paused while a modal dialog of its window is open (a question, the file chooser, Help):
 * the player cannot reach the board then, so the ball should not fly on behind the dialog. Play resumes
 * when the last such dialog closes, unless the game was stopped meanwhile (by loading a board, say).
 */
public final class ModalPause implements AWTEventListener {
    private static final long EVENTS = AWTEvent.WINDOW_EVENT_MASK | AWTEvent.COMPONENT_EVENT_MASK;

    private final Window window;
    private final GameLoop loop;
    private final Set<Dialog> open = new HashSet<>();

    private ModalPause(Window window, GameLoop loop) {
        this.window = window;
        this.loop = loop;
    }

    /** Watches the dialogs of {@code window} until the window is disposed. */
    public static void install(Window window, GameLoop loop) {
        ModalPause pause = new ModalPause(window, loop);
        Toolkit.getDefaultToolkit().addAWTEventListener(pause, EVENTS);
        window.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                Toolkit.getDefaultToolkit().removeAWTEventListener(pause);
            }
        });
    }

    @Override
    public void eventDispatched(AWTEvent event) {
        if (!(event.getSource() instanceof Dialog dialog) || !dialog.isModal() || !ownedByWindow(dialog)) {
            return;
        }
        boolean wasOpen = !open.isEmpty();
        switch (event.getID()) {
            case WindowEvent.WINDOW_OPENED, ComponentEvent.COMPONENT_SHOWN -> open.add(dialog);
            case WindowEvent.WINDOW_CLOSED, ComponentEvent.COMPONENT_HIDDEN -> open.remove(dialog);
            default -> {
                return;
            }
        }
        if (!wasOpen && !open.isEmpty()) {
            loop.hold();
        } else if (wasOpen && open.isEmpty()) {
            loop.release();
        }
    }

    private boolean ownedByWindow(Window w) {
        for (Window owner = w.getOwner(); owner != null; owner = owner.getOwner()) {
            if (owner == window) {
                return true;
            }
        }
        return false;
    }
}
