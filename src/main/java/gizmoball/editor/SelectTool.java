package gizmoball.editor;

import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.TriggerSource;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * Select / Move: a click selects a gizmo, a ball or the outer walls, Shift+click adds to the selection or takes
 * out of it; a drag from empty space selects what its rubber band touches; a drag moves what it grabbed (the whole
 * selection when it grabbed one of several selected), and a drag of a selected absorber's handle resizes it.
 */
final class SelectTool implements ToolHandler {
    private final Editor editor;

    SelectTool(Editor editor) {
        this.editor = editor;
    }

    @Override
    public Optional<String> target(double x, double y) {
        return editor.picking().ballOrGizmoAt(x, y);
    }

    @Override
    public void press(double x, double y) {
        Optional<Handle> handle = editor.handles().stream().filter(h -> h.grabbedAt(x, y)).findFirst();
        Optional<BallView> ball = editor.picking().ballNear(x, y);
        Optional<Gizmo> gizmo = editor.picking().gizmoAt(x, y);
        Optional<String> grabbed = editor.picking().ballOrGizmoAt(x, y);
        if (handle.isPresent()) {
            Handle h = handle.get();
            editor.setStep(new PendingStep.ResizingAbsorber(editor.selectedGizmo().orElseThrow(), h.left(), h.top(),
                    h.right(), h.bottom()));
        } else if (grabbed.isPresent() && editor.severalSelected() && editor.selection().contains(grabbed.get())) {
            editor.setStep(new PendingStep.MovingGroup(editor.selection(), x, y));
        } else if (ball.isPresent()) {
            editor.selectQuietly(ball.get().name());
            editor.setStep(new PendingStep.MovingBall(ball.get(), x, y));
        } else if (gizmo.isPresent()) {
            Gizmo g = gizmo.get();
            editor.selectQuietly(g.name());
            editor.setStep(new PendingStep.MovingGizmo(g, Picking.cell(x) - g.x(), Picking.cell(y) - g.y()));
        } else {
            editor.setStep(new PendingStep.Banding(x, y, x, y, false));
        }
    }

    /** Shift+press: a gizmo or ball goes into the selection or out of it; from empty space a band adds. */
    @Override
    public void pressExtending(double x, double y) {
        Optional<String> there = editor.picking().ballOrGizmoAt(x, y);
        if (there.isPresent()) {
            editor.toggleSelected(there.get());
        } else {
            editor.setStep(new PendingStep.Banding(x, y, x, y, true));
        }
    }

    @Override
    public void drag(double x, double y) {
        if (editor.step() instanceof PendingStep.Banding band) {
            editor.setStep(new PendingStep.Banding(band.x0(), band.y0(), x, y, band.adding()));
            editor.setPreview(null, false);
        } else {
            editor.setPreview(moveTo(x, y), true);
        }
    }

    @Override
    public void release(double x, double y) {
        PendingStep step = editor.step();
        Preview target = moveTo(x, y);
        editor.finishGesture();
        if (step instanceof PendingStep.Banding band) {
            selectBanded(band, x, y);
        } else if (step instanceof PendingStep.MovingGizmo m && target instanceof Preview.Footprint f) {
            Gizmo g = m.gizmo();
            if (f.x() != g.x() || f.y() != g.y()) {
                editor.edit("Moved " + g.name() + " to (" + f.x() + "," + f.y() + ")",
                        b -> b.moveGizmo(g.name(), f.x(), f.y()));
            }
        } else if (step instanceof PendingStep.MovingBall m && target instanceof Preview.BallPlacement p) {
            editor.edit("Moved " + m.ball().name() + " to (" + p.x() + ", " + p.y() + ")",
                    b -> b.moveBall(m.ball().name(), p.x(), p.y()));
        } else if (step instanceof PendingStep.MovingGroup m && target instanceof Preview.Group group) {
            editor.selectionEdits().moveGroup(m.names(), group.dx(), group.dy());
        } else if (step instanceof PendingStep.ResizingAbsorber r && target instanceof Preview.Footprint f) {
            resize(r.absorber(), f);
        }
    }

    private void resize(Gizmo absorber, Preview.Footprint f) {
        if (f.problem().isPresent()) {
            // In the preview's words, as the drag showed it (see PlaceGizmoTool).
            editor.say(f.problem().get());
        } else if (f.x() != absorber.x() || f.y() != absorber.y() || f.width() != absorber.width()
                || f.height() != absorber.height()) {
            editor.edit("Resized " + absorber.name() + " to " + f.width() + "x" + f.height() + " at (" + f.x() + ","
                    + f.y() + ")", b -> b.resizeAbsorber(absorber.name(), f.x(), f.y(), f.x() + f.width(),
                    f.y() + f.height()));
        }
    }

    /**
     * A band that hardly moved is a click on empty space: the outer walls outside the board or on its rim, else
     * nothing. Otherwise the gizmos it touches and the balls whose centres it holds are selected.
     */
    private void selectBanded(PendingStep.Banding band, double x, double y) {
        if (Math.hypot(x - band.x0(), y - band.y0()) < Picking.DRAG_THRESHOLD) {
            if (!band.adding()) {
                editor.select(editor.picking().isWall(x, y) ? TriggerSource.OUTER_WALLS.name() : null);
            }
            return;
        }
        double minX = Math.min(band.x0(), x);
        double maxX = Math.max(band.x0(), x);
        double minY = Math.min(band.y0(), y);
        double maxY = Math.max(band.y0(), y);
        Board board = editor.board();
        List<String> inside = new ArrayList<>();
        for (Gizmo g : board.gizmos()) {
            if (g.x() < maxX && g.x() + g.width() > minX && g.y() < maxY && g.y() + g.height() > minY) {
                inside.add(g.name());
            }
        }
        for (BallView b : board.balls()) {
            if (b.position().x() >= minX && b.position().x() <= maxX && b.position().y() >= minY
                    && b.position().y() <= maxY) {
                inside.add(b.name());
            }
        }
        editor.selectAll(inside, band.adding());
        editor.say(inside.isEmpty() ? "Nothing in the rectangle" : "Selected " + Editor.listed(editor.selection()));
    }

    /** Where the dragged gizmo, ball or group would go; null for a ball not dragged far enough to be a move. */
    private Preview moveTo(double x, double y) {
        if (editor.step() instanceof PendingStep.MovingGizmo m) {
            Gizmo g = m.gizmo();
            int tx = Picking.cell(x) - m.grabDx();
            int ty = Picking.cell(y) - m.grabDy();
            return new Preview.Footprint(tx, ty, g.width(), g.height(),
                    editor.board().placementProblem(g.kind(), tx, ty, g.width(), g.height(), g.name()));
        }
        if (editor.step() instanceof PendingStep.MovingBall m
                && Math.hypot(x - m.pressX(), y - m.pressY()) >= Picking.DRAG_THRESHOLD) {
            BallView ball = m.ball();
            double tx = Picking.snap(ball.position().x() + x - m.pressX());
            double ty = Picking.snap(ball.position().y() + y - m.pressY());
            return new Preview.BallPlacement(tx, ty, ball.velocity().x(), ball.velocity().y(),
                    editor.dryRun(b -> b.moveBall(ball.name(), tx, ty)));
        }
        if (editor.step() instanceof PendingStep.MovingGroup m) {
            return groupMove(m, x, y);
        }
        if (editor.step() instanceof PendingStep.ResizingAbsorber r) {
            return resized(r, x, y);
        }
        return null;
    }

    /** A group with a gizmo moves by whole cells, a group of balls by quarter cells. */
    private Preview.Group groupMove(PendingStep.MovingGroup m, double x, double y) {
        Board board = editor.board();
        boolean cells = m.names().stream().anyMatch(n -> board.gizmo(n).isPresent());
        double dx = cells ? Picking.cell(x) - Picking.cell(m.pressX()) : Picking.snap(x - m.pressX());
        double dy = cells ? Picking.cell(y) - Picking.cell(m.pressY()) : Picking.snap(y - m.pressY());
        List<Preview> parts = new ArrayList<>();
        for (String name : m.names()) {
            board.gizmo(name).ifPresent(g -> parts.add(new Preview.Footprint(g.x() + (int) dx, g.y() + (int) dy,
                    g.width(), g.height(), Optional.empty())));
            board.ball(name).ifPresent(b -> parts.add(new Preview.BallPlacement(b.position().x() + dx,
                    b.position().y() + dy, b.velocity().x(), b.velocity().y(), Optional.empty())));
        }
        Optional<String> problem = dx == 0 && dy == 0 ? Optional.empty()
                : editor.dryRun(b -> b.moveGroup(m.names(), dx, dy));
        return new Preview.Group(parts, m.names(), dx, dy, problem);
    }

    /** The absorber with the grabbed edges on the grid lines nearest the pointer, and whether the board takes it. */
    private Preview.Footprint resized(PendingStep.ResizingAbsorber r, double x, double y) {
        Gizmo a = r.absorber();
        int left = r.left() ? (int) Math.round(x) : a.x();
        int right = r.right() ? (int) Math.round(x) : a.x() + a.width();
        int top = r.top() ? (int) Math.round(y) : a.y();
        int bottom = r.bottom() ? (int) Math.round(y) : a.y() + a.height();
        return new Preview.Footprint(left, top, right - left, bottom - top, editor.board().placementProblem(
                a.kind(), left, top, right - left, bottom - top, a.name()));
    }
}
