package gizmoball.view.editor;

import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.SwingUtilities;
import java.awt.Component;
import java.awt.Container;
import java.awt.GraphicsEnvironment;
import java.awt.Window;
import java.lang.reflect.InvocationTargetException;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.function.BooleanSupplier;

import static org.assertj.core.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

/** For the build-mode window tests: skip without a display, run on the EDT, wait, find components by name. */
final class EditorGui {
    private static final long PATIENCE_MILLIS = 5000;

    private EditorGui() {
    }

    static void assumeDisplay() {
        assumeFalse(GraphicsEnvironment.isHeadless(),
                "build-mode GUI test skipped: no display (run under xvfb-run, as .ci/run does)");
    }

    static <T> T onEdt(Callable<T> body) {
        Object[] result = new Object[1];
        Runnable call = () -> {
            try {
                result[0] = body.call();
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        };
        if (SwingUtilities.isEventDispatchThread()) {
            call.run();
        } else {
            try {
                SwingUtilities.invokeAndWait(call);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException(e);
            } catch (InvocationTargetException e) {
                if (e.getCause() instanceof RuntimeException r && r.getCause() instanceof AssertionError a) {
                    throw a;
                }
                throw new IllegalStateException(e.getCause());
            }
        }
        @SuppressWarnings("unchecked")
        T t = (T) result[0];
        return t;
    }

    static void onEdt(Runnable body) {
        onEdt(() -> {
            body.run();
            return null;
        });
    }

    /** Waits until the condition (evaluated on the EDT) holds; fails naming it after a few seconds. */
    static void await(String what, BooleanSupplier condition) {
        long deadline = System.currentTimeMillis() + PATIENCE_MILLIS;
        while (!onEdt(condition::getAsBoolean)) {
            if (System.currentTimeMillis() > deadline) {
                fail("waited in vain for: " + what);
            }
            try {
                Thread.sleep(20);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException(e);
            }
        }
    }

    /** The component of that type and name inside root (depth first). */
    static <C extends Component> C find(Container root, Class<C> type, String name) {
        return search(root, type, name).orElseThrow(() -> new AssertionError("no " + type.getSimpleName()
                + " named " + name));
    }

    /** A showing menu item of that name in any window (popup menus live in the frame or in their own window). */
    static JMenuItem showingMenuItem(String name) {
        for (Window w : Window.getWindows()) {
            Optional<JMenuItem> item = search(w, JMenuItem.class, name).filter(Component::isShowing);
            if (item.isPresent()) {
                return item.get();
            }
        }
        throw new AssertionError("no showing menu item " + name);
    }

    static JMenuItem menuItem(JMenuBar menus, String text) {
        for (int i = 0; i < menus.getMenuCount(); i++) {
            JMenu menu = menus.getMenu(i);
            for (int j = 0; j < menu.getItemCount(); j++) {
                JMenuItem item = menu.getItem(j);
                if (item != null && text.equals(item.getText())) {
                    return item;
                }
            }
        }
        throw new AssertionError("no menu item " + text);
    }

    private static <C extends Component> Optional<C> search(Container root, Class<C> type, String name) {
        for (Component c : root.getComponents()) {
            if (type.isInstance(c) && name.equals(c.getName())) {
                return Optional.of(type.cast(c));
            }
            if (c instanceof Container inner) {
                Optional<C> found = search(inner, type, name);
                if (found.isPresent()) {
                    return found;
                }
            }
        }
        return Optional.empty();
    }
}
