package gizmoball.editor;

import gizmoball.model.GizmoKind;
import java.util.Locale;

/** How the game names gizmo kinds to the player, in every message and help text: "left flipper", "an absorber". */
public final class Wording {
    private Wording() {
    }

    /** "square", "left flipper". */
    public static String kind(GizmoKind kind) {
        return kind.name().toLowerCase(Locale.ROOT).replace('_', ' ');
    }

    /** "a square", "an absorber". */
    public static String aKind(GizmoKind kind) {
        String name = kind(kind);
        return ("aeiou".indexOf(name.charAt(0)) >= 0 ? "an " : "a ") + name;
    }
}
