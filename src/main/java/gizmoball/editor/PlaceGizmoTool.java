package gizmoball.editor;

import gizmoball.model.Board;
import gizmoball.model.gizmo.GizmoKind;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * Square, Circle, Triangle, Left and Right Flipper: a click places one with its top-left cell there; a drag fills
 * the rectangle from the pressed cell to the pointer with them, side by side, skipping the places that are taken.
 */
final class PlaceGizmoTool implements ToolHandler {
    private final Editor editor;
    private final GizmoKind kind;

    PlaceGizmoTool(Editor editor, GizmoKind kind) {
        this.editor = editor;
        this.kind = kind;
    }

    @Override
    public Preview hover(double x, double y) {
        return editor.footprint(kind, Picking.cell(x), Picking.cell(y), kind.width(), kind.height());
    }

    @Override
    public void press(double x, double y) {
        editor.setStep(new PendingStep.Filling(Picking.cell(x), Picking.cell(y)));
        // Hovering has said already whether the cell is free.
        editor.setPreview(hover(x, y), false);
    }

    @Override
    public void drag(double x, double y) {
        if (editor.step() instanceof PendingStep.Filling f) {
            editor.setPreview(fill(f, x, y), true);
        }
    }

    @Override
    public void release(double x, double y) {
        if (!(editor.step() instanceof PendingStep.Filling f)) {
            return;
        }
        editor.finishGesture();
        if (Picking.cell(x) == f.x0() && Picking.cell(y) == f.y0()) {
            placeOne(x, y);
        } else {
            placeAll(fill(f, x, y));
        }
        editor.setPreview(hover(x, y), false);
    }

    /**
     * A footprint the preview shows refused is refused with the preview's own words, so that hovering and
     * clicking say the same thing, and no message names the gizmo that was never made.
     */
    private void placeOne(double x, double y) {
        int cx = Picking.cell(x);
        int cy = Picking.cell(y);
        Preview footprint = hover(x, y);
        if (footprint.problem().isPresent()) {
            editor.say(footprint.problem().get());
            return;
        }
        String name = editor.names().nextGizmoName(kind);
        if (editor.edit("Placed " + name + " at (" + cx + "," + cy + ")", b -> b.addGizmo(kind, name, cx, cy))) {
            editor.selectQuietly(name);
        }
    }

    /** Every footprint of the fill, in one undo step; the new gizmos are selected. */
    private void placeAll(Preview.Group fill) {
        if (fill.problem().isPresent()) {
            editor.say(fill.problem().get());
            return;
        }
        Board trial = editor.board().copy();
        List<String> names = new ArrayList<>();
        for (Preview part : fill.parts()) {
            Preview.Footprint f = (Preview.Footprint) part;
            String name = new NameGenerator(trial).nextGizmoName(kind);
            trial.addGizmo(kind, name, f.x(), f.y());
            names.add(name);
        }
        if (editor.edit("Placed " + Editor.listed(names), b -> {
            for (int i = 0; i < names.size(); i++) {
                Preview.Footprint f = (Preview.Footprint) fill.parts().get(i);
                b.addGizmo(kind, names.get(i), f.x(), f.y());
            }
        })) {
            editor.selectAll(names, false);
        }
    }

    /**
     * The gizmos a drag from the pressed cell to (x, y) places: side by side from the pressed cell towards the
     * pointer, those whose place is free (refused only when none is).
     */
    private Preview.Group fill(PendingStep.Filling from, double x, double y) {
        int w = kind.width();
        int h = kind.height();
        int columns = Math.abs(Picking.cell(x) - from.x0()) / w + 1;
        int rows = Math.abs(Picking.cell(y) - from.y0()) / h + 1;
        int sx = Picking.cell(x) < from.x0() ? -w : w;
        int sy = Picking.cell(y) < from.y0() ? -h : h;
        List<Preview> fits = new ArrayList<>();
        for (int row = 0; row < rows; row++) {
            for (int column = 0; column < columns; column++) {
                Preview.Footprint f = editor.footprint(kind, from.x0() + column * sx, from.y0() + row * sy, w, h);
                if (f.fits()) {
                    fits.add(f);
                }
            }
        }
        Optional<String> problem = fits.isEmpty()
                ? Optional.of("No room here: every place in the rectangle is taken or off the board")
                : Optional.empty();
        return new Preview.Group(fits, List.of(), 0, 0, problem);
    }
}
