package gizmoball.view;

import gizmoball.boardfile.Decimals;
import gizmoball.boardfile.KeyCodes;
import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;
import java.util.stream.Collectors;

/**
 * The player's view of a board's key bindings: one line per key and gizmo, saying what the gizmo is and how
 * the key is used, e.g. "Z: left flipper LF (hold)" or "Space: absorber A (press)".
 */
final class KeyHelp {
    private KeyHelp() {
    }

    private record KeyAndGizmo(int keyCode, String gizmo) {
    }

    /**
     * What a player new to the game is told once: how to start, and the keys that play the board, as many of them
     * as {@code fits} (whole entries, never a word cut), the rest left to Help > Keys of this board.
     */
    static String firstRunHint(Board board, Predicate<String> fits) {
        List<String> keys = describe(board);
        String hint = "Press Start (Ctrl+G) to play" + (keys.isEmpty() ? "" : "; keys: " + String.join(", ", keys))
                + ". Help > Keys of this board (Ctrl+K) lists them again.";
        for (int shown = keys.size() - 1; shown >= 0 && !fits.test(hint); shown--) {
            hint = "Press Start (Ctrl+G) to play; " + (shown == 0 ? "the keys"
                    : "keys: " + String.join(", ", keys.subList(0, shown)) + " and more")
                    + ": Help > Keys of this board (Ctrl+K).";
        }
        return hint;
    }

    static List<String> describe(Board board) {
        Map<KeyAndGizmo, List<KeyBinding>> bindings = new LinkedHashMap<>();
        for (KeyBinding b : board.keyBindings()) {
            bindings.computeIfAbsent(new KeyAndGizmo(b.keyCode(), b.gizmo()), k -> new ArrayList<>()).add(b);
        }
        List<String> lines = new ArrayList<>(bindings.entrySet().stream().map(e -> {
            KeyAndGizmo k = e.getKey();
            GizmoKind kind = board.gizmo(k.gizmo()).map(Gizmo::kind).orElse(null);
            boolean plunger = board.gizmo(k.gizmo()).filter(g -> g.plunger().isPresent()).isPresent();
            return KeyCodes.name(k.keyCode()) + ": " + (plunger ? "plunger " : kindName(kind)) + k.gizmo()
                    + " (" + (plunger ? "hold to pull, release to launch" : use(kind, e.getValue())) + ")";
        }).toList());
        board.gameRules().nudge().ifPresent(n -> lines.add(KeyCodes.name(n.leftKey()) + ", "
                + KeyCodes.name(n.rightKey()) + ", " + KeyCodes.name(n.upKey()) + ": nudge left, right, up"));
        return lines;
    }

    /** "left flipper " for LEFT_FLIPPER; nothing for a name the board does not hold. */
    private static String kindName(GizmoKind kind) {
        return kind == null ? "" : kind.displayName() + " ";
    }

    /**
     * A gizmo raised on the press and lowered on the release at once (a flipper, unless told otherwise) is held;
     * anything else acts on the edges, each with its action and delay where the binding gives them.
     */
    private static String use(GizmoKind kind, List<KeyBinding> bindings) {
        Map<KeyEdge, Action> actions = new EnumMap<>(KeyEdge.class);
        bindings.forEach(b -> actions.put(b.edge(), kind == null ? null
                : b.order().action().orElse(b.edge().actionOf(kind))));
        boolean atOnce = bindings.stream().allMatch(b -> b.order().delay() == 0);
        if (atOnce && actions.size() == 2 && actions.get(KeyEdge.DOWN) == Action.RAISE
                && actions.get(KeyEdge.UP) == Action.LOWER) {
            return "hold";
        }
        if (bindings.size() == 2 && bindings.stream().allMatch(b -> b.order().isDefault())) {
            return "press and release";
        }
        return bindings.stream().map(b -> (b.edge() == KeyEdge.UP ? "release" : "press")
                + (b.order().isDefault() ? "" : ": " + actions.get(b.edge()).word()
                        + (b.order().delay() == 0 ? "" : " after " + Decimals.format(b.order().delay()) + " s")))
                .collect(Collectors.joining(", "));
    }
}
