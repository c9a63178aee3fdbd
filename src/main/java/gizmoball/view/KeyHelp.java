package gizmoball.view;

import gizmoball.model.KeyBinding;
import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/** The player's view of a board's key bindings: one line per key and gizmo, e.g. "Z: LF (down, up)". */
final class KeyHelp {
    private KeyHelp() {
    }

    static List<String> describe(List<KeyBinding> bindings) {
        Map<String, List<String>> edges = new LinkedHashMap<>();
        for (KeyBinding b : bindings) {
            edges.computeIfAbsent(KeyEvent.getKeyText(b.keyCode()) + ": " + b.gizmo(), k -> new ArrayList<>())
                    .add(b.edge().name().toLowerCase(Locale.ROOT));
        }
        List<String> lines = new ArrayList<>();
        edges.forEach((keyAndGizmo, e) -> lines.add(keyAndGizmo + " (" + String.join(", ", e) + ")"));
        return lines;
    }
}
