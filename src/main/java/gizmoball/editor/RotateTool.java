package gizmoball.editor;

import gizmoball.model.gizmo.Gizmo;
import java.util.Optional;

/** Rotate: a click turns a gizmo 90 degrees clockwise. */
final class RotateTool implements ToolHandler {
    private final Editor editor;

    RotateTool(Editor editor) {
        this.editor = editor;
    }

    @Override
    public Optional<String> target(double x, double y) {
        return editor.picking().gizmoAt(x, y).map(Gizmo::name);
    }

    @Override
    public void press(double x, double y) {
        editor.picking().gizmoAt(x, y).ifPresentOrElse(g -> {
            editor.selectQuietly(g.name());
            editor.selectionEdits().rotate(g);
        }, () -> editor.say("No gizmo here to rotate"));
    }
}
