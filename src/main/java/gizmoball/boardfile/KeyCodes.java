package gizmoball.boardfile;

import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import java.awt.event.KeyEvent;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.HashSet;
import java.util.Locale;
import java.util.Set;

/**
 * The key codes a board file may bind: the values of {@link KeyEvent}'s {@code VK_} constants
 * (except {@code VK_UNDEFINED}). Read by reflection so the list is the running JDK's own.
 * Loading KeyEvent needs no display, so this works headless. Also the one place that names keys and key
 * bindings to the player, so that the status line, the overlay and the help say them the same way.
 */
public final class KeyCodes {
    private static final Set<Integer> CODES = constantValues();

    private KeyCodes() {
    }

    static boolean isKnown(int keyCode) {
        return CODES.contains(keyCode);
    }

    /** The key as the player knows it: "Z", "Space", "Slash". */
    public static String name(int keyCode) {
        return KeyEvent.getKeyText(keyCode);
    }

    /** "down" or "up", as in the board file. */
    public static String edge(KeyEdge edge) {
        return edge.name().toLowerCase(Locale.ROOT);
    }

    /** "key Z down \u2192 LF". */
    public static String describe(KeyBinding binding) {
        return "key " + name(binding.keyCode()) + " " + edge(binding.edge()) + " \u2192 " + binding.gizmo();
    }

    private static Set<Integer> constantValues() {
        Set<Integer> codes = new HashSet<>();
        for (Field field : KeyEvent.class.getFields()) {
            int modifiers = field.getModifiers();
            if (field.getName().startsWith("VK_") && !field.getName().equals("VK_UNDEFINED")
                    && Modifier.isStatic(modifiers) && field.getType() == int.class) {
                try {
                    codes.add(field.getInt(null));
                } catch (IllegalAccessException e) {
                    throw new IllegalStateException("public constant " + field + " is not readable", e);
                }
            }
        }
        return Set.copyOf(codes);
    }
}
