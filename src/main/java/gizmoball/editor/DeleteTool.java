package gizmoball.editor;

import java.util.Optional;

/** Delete: a click removes a ball or gizmo (a ball first: it may sit on a gizmo's cell). */
final class DeleteTool implements ToolHandler {
    private final Editor editor;

    DeleteTool(Editor editor) {
        this.editor = editor;
    }

    @Override
    public Optional<String> target(double x, double y) {
        return editor.picking().ballOrGizmoAt(x, y);
    }

    @Override
    public void press(double x, double y) {
        target(x, y).ifPresentOrElse(editor.selectionEdits()::delete, () -> editor.say("Nothing here to delete"));
    }
}
