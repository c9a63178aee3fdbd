package gizmoball.model.gizmo;

/**
 * A 1x1 cell that is solid while closed and nothing while open, switched by its actions. A gate told to close while a
 * ball lies in its cell waits, open, until the cell is clear (a {@link SwitchedCell}, as a drop target is).
 */
public final class Gate extends SwitchedCell implements GateView {

    Gate(String name, int x, int y) {
        super(name, GizmoKind.GATE, x, y);
    }

    private Gate(Gate other) {
        super(other);
    }

    /** Hit, it stays as it is: only an order opens it. */
    @Override
    public boolean fallsWhenHit() {
        return false;
    }

    @Override
    public boolean isOpen() {
        return !isSolid();
    }

    @Override
    public boolean isClosing() {
        return isWaiting();
    }

    /** Opens, closes or toggles it through the board, which says when a gate may close. */
    @Override
    public void perform(Action action, Surroundings around) {
        switch (action) {
            case OPEN -> around.switchCell(this, false);
            case CLOSE -> around.switchCell(this, true);
            case TOGGLE -> around.switchCell(this, isOpen() && !isClosing());   // waiting to close: stays open
            default -> {
            }
        }
    }

    @Override
    public Gate copy() {
        return new Gate(this);
    }
}
