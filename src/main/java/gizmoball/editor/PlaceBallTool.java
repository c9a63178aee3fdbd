package gizmoball.editor;

/**
 * Ball: press where the centre goes (snapped to a quarter cell), drag to give it a velocity
 * ({@link Editor#VELOCITY_PER_DRAG} L/s per L dragged), release to place it.
 */
final class PlaceBallTool implements ToolHandler {
    private final Editor editor;

    PlaceBallTool(Editor editor) {
        this.editor = editor;
    }

    @Override
    public Preview hover(double x, double y) {
        return placement(Picking.snap(x), Picking.snap(y), 0, 0);
    }

    @Override
    public void press(double x, double y) {
        editor.setStep(new PendingStep.PlacingBall(Picking.snap(x), Picking.snap(y), x, y));
        drag(x, y);
    }

    @Override
    public void drag(double x, double y) {
        if (editor.step() instanceof PendingStep.PlacingBall b) {
            editor.setPreview(placement(b, x, y), true);
        }
    }

    @Override
    public void release(double x, double y) {
        if (!(editor.step() instanceof PendingStep.PlacingBall b)) {
            return;
        }
        Preview.BallPlacement p = placement(b, x, y);
        editor.finishGesture();
        String name = editor.names().nextBallName();
        if (editor.edit("Placed ball " + name + " moving at (" + p.vx() + ", " + p.vy() + ") L/s",
                board -> board.addBall(name, p.x(), p.y(), p.vx(), p.vy()))) {
            editor.selectQuietly(name);
        }
    }

    /** Measured from where the button went down, not from the snapped centre: a click is no velocity. */
    private Preview.BallPlacement placement(PendingStep.PlacingBall b, double x, double y) {
        boolean still = Math.hypot(x - b.pressX(), y - b.pressY()) < Picking.DRAG_THRESHOLD;
        return still ? placement(b.x(), b.y(), 0, 0)
                : placement(b.x(), b.y(), velocity(x - b.pressX()), velocity(y - b.pressY()));
    }

    private Preview.BallPlacement placement(double x, double y, double vx, double vy) {
        String name = editor.names().nextBallName();
        return new Preview.BallPlacement(x, y, vx, vy, editor.dryRun(b -> b.addBall(name, x, y, vx, vy)));
    }

    private static double velocity(double drag) {
        // Whole L/s: typed-looking numbers in the properties panel and in saved files.
        return Math.round(drag * Editor.VELOCITY_PER_DRAG);
    }
}
