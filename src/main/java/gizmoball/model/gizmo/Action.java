package gizmoball.model.gizmo;

import java.util.Arrays;
import java.util.Locale;
import java.util.Optional;

/**
 * What a connection or a key binding can tell its target to do; each kind says which it can
 * ({@link GizmoKind#actions}). Every gizmo can flash: light up, as a hit lights it, and do nothing else.
 */
public enum Action {
    /** A flipper swings to its active stop and stays there; a drop target rises, as soon as no ball is in its cell. */
    RAISE,
    /** A flipper swings back to rest. */
    LOWER,
    /** A flipper swings to the stop it is not swinging to; a gate opens if closed, closes if open. */
    TOGGLE,
    /** An absorber fires its longest-held ball. */
    FIRE,
    /** A gate lets balls through. */
    OPEN,
    /** A gate becomes solid, as soon as no ball is in its cell. */
    CLOSE,
    /** A spawner adds a ball at its mouth. */
    SPAWN,
    /** A spinner turns the other way. */
    REVERSE,
    /** A spinner turns. */
    START,
    /** A spinner stops where it is. */
    STOP,
    /** Lights up and does nothing else. */
    FLASH;

    /** How board files, the editor and help name it: "raise". */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The action a word names, in any letter case. */
    public static Optional<Action> named(String word) {
        return Arrays.stream(values()).filter(a -> a.word().equalsIgnoreCase(word)).findFirst();
    }
}
