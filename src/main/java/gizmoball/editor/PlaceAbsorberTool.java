package gizmoball.editor;

import gizmoball.model.gizmo.GizmoKind;

/**
 * A kind sized by its corners (an absorber): press on one corner cell, drag to the opposite one, release to place it.
 */
final class PlaceAbsorberTool implements ToolHandler {
    private final Editor editor;
    private final GizmoKind kind;

    PlaceAbsorberTool(Editor editor, GizmoKind kind) {
        this.editor = editor;
        this.kind = kind;
    }

    @Override
    public Preview hover(double x, double y) {
        return footprint(Picking.cell(x), Picking.cell(y), Picking.cell(x), Picking.cell(y));
    }

    @Override
    public void press(double x, double y) {
        editor.setStep(new PendingStep.DraggingAbsorber(Picking.cell(x), Picking.cell(y)));
        drag(x, y);
    }

    @Override
    public void drag(double x, double y) {
        if (editor.step() instanceof PendingStep.DraggingAbsorber a) {
            editor.setPreview(footprint(a.x0(), a.y0(), Picking.cell(x), Picking.cell(y)), true);
        }
    }

    @Override
    public void release(double x, double y) {
        if (!(editor.step() instanceof PendingStep.DraggingAbsorber a)) {
            return;
        }
        Preview.Footprint f = footprint(a.x0(), a.y0(), Picking.cell(x), Picking.cell(y));
        editor.finishGesture();
        if (f.problem().isPresent()) {
            // In the preview's words, as the drag showed it (see PlaceGizmoTool).
            editor.say(f.problem().get());
            return;
        }
        String name = editor.names().nextGizmoName(kind);
        if (editor.edit("Placed absorber " + name, b -> b.addAbsorber(name, f.x(), f.y(),
                f.x() + f.width(), f.y() + f.height()))) {
            editor.selectQuietly(name);
        }
    }

    private Preview.Footprint footprint(int x0, int y0, int x1, int y1) {
        return editor.footprint(kind, Math.min(x0, x1), Math.min(y0, y1), Math.abs(x1 - x0) + 1,
                Math.abs(y1 - y0) + 1);
    }
}
