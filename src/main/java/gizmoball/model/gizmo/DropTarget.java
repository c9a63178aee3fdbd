package gizmoball.model.gizmo;

/**
 * A 1x1 cell that is solid (up) until a ball hits it, then nothing (down) until told to rise ({@link Action#RAISE}).
 * A hit drops it at the end of the tick (the board's play rules watch the tick's hits), so the ball bounces off it
 * first; told to rise while a ball lies in its cell it waits down until the cell is clear (a {@link SwitchedCell}, as
 * a gate is).
 */
public final class DropTarget extends SwitchedCell implements DropTargetView {

    DropTarget(String name, int x, int y) {
        super(name, GizmoKind.DROP_TARGET, x, y);
    }

    private DropTarget(DropTarget other) {
        super(other);
    }

    /** Hit, it goes down. */
    @Override
    public boolean fallsWhenHit() {
        return true;
    }

    @Override
    public boolean isDown() {
        return !isSolid();
    }

    @Override
    public boolean isRising() {
        return isWaiting();
    }

    /** Rises through the board, which says when the cell is clear. */
    @Override
    public void perform(Action action, Surroundings around) {
        if (action == Action.RAISE) {
            around.switchCell(this, true);
        }
    }

    @Override
    public DropTarget copy() {
        return new DropTarget(this);
    }
}
