package gizmoball.boardfile;

import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import java.awt.event.KeyEvent;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.OptionalInt;
import java.util.Set;

/**
 * The key codes a board file may bind: the values of {@link KeyEvent}'s {@code VK_} constants
 * (except {@code VK_UNDEFINED}). Read by reflection so the list is the running JDK's own.
 * Loading KeyEvent needs no display, so this works headless. Also the one place that names keys and key
 * bindings to the player, so that the status line, the overlay and the help say them the same way.
 */
public final class KeyCodes {
    private static final String PREFIX = "VK_";
    private static final Map<String, Integer> BY_NAME = constants();
    private static final Set<Integer> CODES = Set.copyOf(BY_NAME.values());

    private KeyCodes() {
    }

    public static boolean isKnown(int keyCode) {
        return CODES.contains(keyCode);
    }

    /** The code of a KeyEvent key name in any letter case, with or without its VK_ prefix: Space, q, vk_left. */
    public static OptionalInt named(String name) {
        String upper = name.toUpperCase(Locale.ROOT);
        Integer code = BY_NAME.get(upper.startsWith(PREFIX) ? upper.substring(PREFIX.length()) : upper);
        return code == null ? OptionalInt.empty() : OptionalInt.of(code);
    }

    /** The key as the player knows it: "Z", "Space", "Slash". */
    public static String name(int keyCode) {
        return KeyEvent.getKeyText(keyCode);
    }

    /** "down", "up" or "change", as in the board file. */
    public static String edge(KeyEdge edge) {
        return edge.name().toLowerCase(Locale.ROOT);
    }

    /** "key Z down \u2192 LF". */
    public static String describe(KeyBinding binding) {
        return "key " + name(binding.keyCode()) + " " + edge(binding.edge()) + " \u2192 " + binding.gizmo()
                + OrderWords.of(binding.order());
    }

    /** Name without the prefix -> code. */
    private static Map<String, Integer> constants() {
        Map<String, Integer> codes = new HashMap<>();
        for (Field field : KeyEvent.class.getFields()) {
            int modifiers = field.getModifiers();
            if (field.getName().startsWith(PREFIX) && !field.getName().equals("VK_UNDEFINED")
                    && Modifier.isStatic(modifiers) && field.getType() == int.class) {
                try {
                    codes.put(field.getName().substring(PREFIX.length()), field.getInt(null));
                } catch (IllegalAccessException e) {
                    throw new IllegalStateException("public constant " + field + " is not readable", e);
                }
            }
        }
        return Map.copyOf(codes);
    }
}
