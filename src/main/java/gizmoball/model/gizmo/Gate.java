package gizmoball.model.gizmo;

import java.util.List;

import physics.Vect;

/**
 * A 1x1 cell that is solid (a square that reflects as a bumper does) while closed and nothing while open, switched by
 * its actions. A gate told to close while a ball lies in its cell waits, open, until the cell is clear: no ball is
 * ever inside a closed gate (the board decides when, {@link #closedOver}).
 */
public final class Gate extends GizmoBase implements GateView {
    private static final Shape NOTHING = new Shape(List.of(), List.of());
    private boolean open;
    /** Told to close while a ball was in the way: it closes as soon as the cell is clear. */
    private boolean closing;

    Gate(String name, int x, int y) {
        super(name, GizmoKind.GATE, x, y);
        rebuildShape();
    }

    private Gate(Gate other) {
        super(other);
        this.open = other.open;
        this.closing = other.closing;
    }

    @Override
    public double reflectionCoefficient() {
        return 1.0;
    }

    @Override
    public boolean isOpen() {
        return open;
    }

    @Override
    public boolean isClosing() {
        return closing;
    }

    private List<Vect> outline() {
        return List.of(new Vect(x(), y()), new Vect(x() + 1, y()), new Vect(x() + 1, y() + 1), new Vect(x(), y() + 1));
    }

    @Override
    Shape buildShape() {
        return open ? NOTHING : Shape.polygon(outline());
    }

    /** Signed distance to its solid body: its cell while closed, none (infinitely far) while open. */
    @Override
    public double signedDistance(Vect p) {
        return open ? Double.POSITIVE_INFINITY : closedOver(p);
    }

    /**
     * Signed distance from p to the cell it fills when closed, open or not: the board asks it before closing the
     * gate. For the board and its loop, not for views.
     */
    public double closedOver(Vect p) {
        return Solids.toConvexPolygon(outline(), p);
    }

    /** Opens, closes or toggles it through the board, which says when a gate may close. */
    @Override
    public void perform(Action action, Surroundings around) {
        switch (action) {
            case OPEN -> around.switchGate(this, true);
            case CLOSE -> around.switchGate(this, false);
            case TOGGLE -> around.switchGate(this, !open || closing);   // waiting to close: stays open
            default -> {
            }
        }
    }

    /**
     * Opens it, or closes it (and rebuilds its shape), or, with {@code waiting}, marks it as waiting to close. For
     * the board and its loop, not for views.
     */
    public void set(boolean nowOpen, boolean waiting) {
        open = nowOpen;
        closing = waiting;
        rebuildShape();
    }

    @Override
    public Gate copy() {
        return new Gate(this);
    }
}
