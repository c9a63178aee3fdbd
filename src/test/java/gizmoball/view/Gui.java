package gizmoball.view;

import static org.assertj.core.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.awt.Component;
import java.awt.Container;
import java.awt.GraphicsEnvironment;
import java.awt.Window;
import java.lang.reflect.InvocationTargetException;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.SwingUtilities;

/**
 * Helpers for the tests that open real windows: skip without a display, run on the EDT, wait for conditions.
 * Public so that build mode's GUI tests (gizmoball.view.editor) use them too instead of a copy.
 */
public final class Gui {
    private static final long PATIENCE_MILLIS = 5000;

    private Gui() {
    }

    /** Skips the calling test, saying why, unless windows can really be opened here (see {@link DisplayCheck}). */
    public static void assumeDisplay() {
        assumeFalse(GraphicsEnvironment.isHeadless(), () -> "GUI test skipped: "
                + DisplayCheck.reason().orElse("no display") + " (run under xvfb-run, as .ci/run does)");
    }

    public static <T> T onEdt(Callable<T> body) {
        if (SwingUtilities.isEventDispatchThread()) {
            try {
                return body.call();
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }
        Object[] result = new Object[1];
        try {
            SwingUtilities.invokeAndWait(() -> {
                try {
                    result[0] = body.call();
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        } catch (InvocationTargetException e) {
            throw new IllegalStateException(e.getCause());
        }
        @SuppressWarnings("unchecked")
        T t = (T) result[0];
        return t;
    }

    public static void onEdt(Runnable body) {
        onEdt(() -> {
            body.run();
            return null;
        });
    }

    /** Waits until {@code condition} (evaluated on the EDT) holds; fails with {@code what} after a few seconds. */
    /**
     * Disposes every window and waits until their closing has been handled (a window's closed listener, which may
     * write settings, runs on the event thread after the dispose): settings may then be removed without a listener
     * writing to a removed node.
     */
    public static void closeAllWindows() {
        for (Window w : Window.getWindows()) {
            onEdt(w::dispose);
        }
        onEdt(() -> { });
    }

    public static void await(String what, BooleanSupplier condition) {
        long deadline = System.currentTimeMillis() + PATIENCE_MILLIS;
        while (!onEdt(condition::getAsBoolean)) {
            if (System.currentTimeMillis() > deadline) {
                fail("waited in vain for: " + what);
            }
            sleep(20);
        }
    }

    public static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        }
    }

    /** Clicks the menu item with that text, as a player would (through its action). */
    public static void clickMenu(JMenuBar menus, String text) {
        onEdt(() -> menuItem(menus, text).doClick(0));
    }

    /** The item with that text in any menu or submenu. */
    public static JMenuItem menuItem(JMenuBar menus, String text) {
        for (int i = 0; i < menus.getMenuCount(); i++) {
            Optional<JMenuItem> found = menuItem(menus.getMenu(i), text);
            if (found.isPresent()) {
                return found.get();
            }
        }
        throw new AssertionError("no menu item " + text);
    }

    private static Optional<JMenuItem> menuItem(JMenu menu, String text) {
        for (int j = 0; j < menu.getItemCount(); j++) {
            JMenuItem item = menu.getItem(j);
            if (item != null && text.equals(item.getText())) {
                return Optional.of(item);
            }
            if (item instanceof JMenu submenu) {
                Optional<JMenuItem> found = menuItem(submenu, text);
                if (found.isPresent()) {
                    return found;
                }
            }
        }
        return Optional.empty();
    }

    public static Optional<Window> showingWindow(String name) {
        return onEdt(() -> {
            for (Window w : Window.getWindows()) {
                if (w.isShowing() && name.equals(w.getName())) {
                    return Optional.of(w);
                }
            }
            return Optional.<Window>empty();
        });
    }

    /** The first component of that type inside {@code root} (depth first) that {@code which} accepts. */
    public static <C extends Component> Optional<C> find(Container root, Class<C> type, Predicate<C> which) {
        for (Component c : root.getComponents()) {
            if (type.isInstance(c) && which.test(type.cast(c))) {
                return Optional.of(type.cast(c));
            }
            if (c instanceof Container inner) {
                Optional<C> found = find(inner, type, which);
                if (found.isPresent()) {
                    return found;
                }
            }
        }
        return Optional.empty();
    }
}
