package gizmoball.view;

import java.awt.Toolkit;
import java.lang.reflect.Field;
import java.util.Optional;

/**
 * The X11 window class (WM_CLASS), by which desktops match a window to its menu entry and icon. The JDK
 * derives it from the main class ("gizmoball-Main") and offers no API to set it, so it is set on the X
 * toolkit's field, which needs {@code --add-opens java.desktop/sun.awt.X11=ALL-UNNAMED} (the jar's manifest,
 * the start scripts and the app image pass it). Elsewhere, or without that, the default stays.
 */
public final class WindowClass {
    private static final String FIELD = "awtAppClassName";

    private WindowClass() {
    }

    /** Call before the first window opens. Returns whether the name was set. */
    public static boolean name(String name) {
        try {
            Toolkit toolkit = Toolkit.getDefaultToolkit();
            Field field = toolkit.getClass().getDeclaredField(FIELD);
            field.setAccessible(true);
            field.set(null, name);
            return true;
        } catch (ReflectiveOperationException | RuntimeException notX11OrNotOpened) {
            return false;
        }
    }

    /** The class name windows get now, if this toolkit has one. */
    public static Optional<String> current() {
        try {
            Toolkit toolkit = Toolkit.getDefaultToolkit();
            Field field = toolkit.getClass().getDeclaredField(FIELD);
            field.setAccessible(true);
            return Optional.ofNullable((String) field.get(null));
        } catch (ReflectiveOperationException | RuntimeException notX11OrNotOpened) {
            return Optional.empty();
        }
    }
}
