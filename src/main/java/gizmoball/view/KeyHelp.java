package gizmoball.view;

import gizmoball.boardfile.KeyCodes;
import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The player's view of a board's key bindings: one line per key and gizmo, saying what the gizmo is and how
 * the key is used, e.g. "Z: left flipper LF (hold)" or "Space: absorber A (press)".
 */
final class KeyHelp {
    private KeyHelp() {
    }

    private record KeyAndGizmo(int keyCode, String gizmo) {
    }

    /** What a player new to the game is told once: how to start, and the keys that play the board. */
    static String firstRunHint(Board board) {
        List<String> keys = describe(board);
        return "Press Start (Ctrl+G) to play" + (keys.isEmpty() ? "" : "; keys: " + String.join(", ", keys))
                + ". Help > Keys of this board (Ctrl+K) lists them again.";
    }

    static List<String> describe(Board board) {
        Map<KeyAndGizmo, Set<KeyEdge>> edges = new LinkedHashMap<>();
        for (KeyBinding b : board.keyBindings()) {
            edges.computeIfAbsent(new KeyAndGizmo(b.keyCode(), b.gizmo()), k -> EnumSet.noneOf(KeyEdge.class))
                    .add(b.edge());
        }
        return edges.entrySet().stream().map(e -> {
            KeyAndGizmo k = e.getKey();
            GizmoKind kind = board.gizmo(k.gizmo()).map(Gizmo::kind).orElse(null);
            return KeyCodes.name(k.keyCode()) + ": " + kindName(kind) + k.gizmo()
                    + " (" + use(kind, e.getValue()) + ")";
        }).toList();
    }

    /** "left flipper " for LEFT_FLIPPER; nothing for a name the board does not hold. */
    private static String kindName(GizmoKind kind) {
        return kind == null ? "" : kind.displayName() + " ";
    }

    /** A flipper driven by both edges stays up while the key is held; anything else acts on the edges. */
    private static String use(GizmoKind kind, Set<KeyEdge> edges) {
        boolean flipper = kind == GizmoKind.LEFT_FLIPPER || kind == GizmoKind.RIGHT_FLIPPER;
        if (edges.size() == 2) {
            return flipper ? "hold" : "press and release";
        }
        return edges.contains(KeyEdge.DOWN) ? "press" : "release";
    }
}
