package gizmoball.editor;

import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.TriggerSource;
import java.util.Optional;

/** Select / Move: a click selects a gizmo, a ball or the outer walls; a drag moves the gizmo or ball. */
final class SelectTool implements ToolHandler {
    private final Editor editor;

    SelectTool(Editor editor) {
        this.editor = editor;
    }

    @Override
    public Optional<String> target(double x, double y) {
        return editor.ballOrGizmoAt(x, y);
    }

    @Override
    public void press(double x, double y) {
        Optional<BallView> ball = editor.ballNear(x, y);
        Optional<Gizmo> gizmo = editor.gizmoAt(x, y);
        if (ball.isPresent()) {
            editor.selectQuietly(ball.get().name());
            editor.setStep(new PendingStep.MovingBall(ball.get(), x, y));
        } else if (gizmo.isPresent()) {
            Gizmo g = gizmo.get();
            editor.selectQuietly(g.name());
            editor.setStep(new PendingStep.MovingGizmo(g, Editor.cell(x) - g.x(), Editor.cell(y) - g.y()));
        } else {
            editor.select(editor.isWall(x, y) ? TriggerSource.OUTER_WALLS.name() : null);
        }
    }

    @Override
    public void drag(double x, double y) {
        editor.setPreview(moveTo(x, y), true);
    }

    @Override
    public void release(double x, double y) {
        PendingStep step = editor.step();
        Preview target = moveTo(x, y);
        editor.finishGesture();
        if (step instanceof PendingStep.MovingGizmo m && target instanceof Preview.Footprint f) {
            Gizmo g = m.gizmo();
            if (f.x() != g.x() || f.y() != g.y()) {
                editor.edit("Moved " + g.name() + " to (" + f.x() + "," + f.y() + ")",
                        b -> b.moveGizmo(g.name(), f.x(), f.y()));
            }
        } else if (step instanceof PendingStep.MovingBall m && target instanceof Preview.BallPlacement p) {
            editor.edit("Moved " + m.ball().name() + " to (" + p.x() + ", " + p.y() + ")",
                    b -> b.moveBall(m.ball().name(), p.x(), p.y()));
        }
    }

    /** Where the dragged gizmo or ball would go; null for a ball not dragged far enough to be a move. */
    private Preview moveTo(double x, double y) {
        if (editor.step() instanceof PendingStep.MovingGizmo m) {
            Gizmo g = m.gizmo();
            int tx = Editor.cell(x) - m.grabDx();
            int ty = Editor.cell(y) - m.grabDy();
            return new Preview.Footprint(tx, ty, g.width(), g.height(),
                    editor.board().placementProblem(g.kind(), tx, ty, g.width(), g.height(), g.name()));
        }
        if (editor.step() instanceof PendingStep.MovingBall m
                && Math.hypot(x - m.pressX(), y - m.pressY()) >= Editor.DRAG_THRESHOLD) {
            BallView ball = m.ball();
            double tx = Editor.snap(ball.position().x() + x - m.pressX());
            double ty = Editor.snap(ball.position().y() + y - m.pressY());
            return new Preview.BallPlacement(tx, ty, ball.velocity().x(), ball.velocity().y(),
                    editor.dryRun(b -> b.moveBall(ball.name(), tx, ty)));
        }
        return null;
    }
}
