package gizmoball.view.editor;

import gizmoball.view.Gui;
import javax.swing.JMenuItem;
import gizmoball.view.Gui;
import java.awt.Component;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import java.awt.Container;
import java.awt.Window;
import java.util.Optional;

/** For the build-mode window tests, on top of {@link Gui}: components found by their names. */
final class EditorGui {
    private EditorGui() {
    }

    /** The component of that type and name inside root (depth first). */
    static <C extends Component> C find(Container root, Class<C> type, String name) {
        return named(root, type, name).orElseThrow(() -> new AssertionError("no " + type.getSimpleName()
                + " named " + name));
    }

    /** A showing menu item of that name in any window (popup menus live in the frame or in their own window). */
    static JMenuItem showingMenuItem(String name) {
        for (Window w : Window.getWindows()) {
            Optional<JMenuItem> item = named(w, JMenuItem.class, name).filter(Component::isShowing);
            if (item.isPresent()) {
                return item.get();
            }
        }
        throw new AssertionError("no showing menu item " + name);
    }

    private static <C extends Component> Optional<C> named(Container root, Class<C> type, String name) {
        return Gui.find(root, type, c -> name.equals(c.getName()));
    }

    /** The item of any menu of {@code menus} with that component name (its text may say what it would do). */
    static JMenuItem menuItemNamed(JMenuBar menus, String name) {
        return Gui.onEdt(() -> {
            for (int i = 0; i < menus.getMenuCount(); i++) {
                JMenu menu = menus.getMenu(i);
                for (int j = 0; j < menu.getItemCount(); j++) {
                    JMenuItem item = menu.getItem(j);
                    if (item != null && name.equals(item.getName())) {
                        return item;
                    }
                }
            }
            throw new AssertionError("no menu item named " + name);
        });
    }
}
