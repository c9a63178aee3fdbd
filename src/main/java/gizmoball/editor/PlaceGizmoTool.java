package gizmoball.editor;

import gizmoball.model.gizmo.GizmoKind;

/** Square, Circle, Triangle, Left and Right Flipper: a click places one with its top-left cell there. */
final class PlaceGizmoTool implements ToolHandler {
    private final Editor editor;
    private final GizmoKind kind;

    PlaceGizmoTool(Editor editor, GizmoKind kind) {
        this.editor = editor;
        this.kind = kind;
    }

    @Override
    public Preview hover(double x, double y) {
        return editor.footprint(kind, Editor.cell(x), Editor.cell(y), kind.width(), kind.height());
    }

    /**
     * A footprint the preview shows refused is refused with the preview's own words, so that hovering and
     * clicking say the same thing, and no message names the gizmo that was never made.
     */
    @Override
    public void press(double x, double y) {
        int cx = Editor.cell(x);
        int cy = Editor.cell(y);
        Preview footprint = hover(x, y);
        if (footprint.problem().isPresent()) {
            editor.say(footprint.problem().get());
            editor.setPreview(footprint, false);
            return;
        }
        String name = editor.names().nextGizmoName(kind);
        if (editor.edit("Placed " + name + " at (" + cx + "," + cy + ")", b -> b.addGizmo(kind, name, cx, cy))) {
            editor.selectQuietly(name);
        }
        // The cell is now taken: refresh the preview without announcing the overlap over the success message.
        editor.setPreview(hover(x, y), false);
    }
}
