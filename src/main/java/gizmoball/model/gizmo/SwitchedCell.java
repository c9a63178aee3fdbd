package gizmoball.model.gizmo;

import java.util.List;

import physics.Vect;

/**
 * A 1x1 cell that is solid (a square that reflects as a bumper does) or nothing, switched in play: a gate (open is
 * nothing) and a drop target (down is nothing). Told to become solid while a ball lies in its cell, it waits as nothing
 * until the cell is clear, so no ball is ever inside it; the board decides when ({@link #solidOver}), through one rule
 * for both kinds (the board's {@code Play.switchCell}).
 */
public abstract sealed class SwitchedCell extends GizmoBase permits Gate, DropTarget {
    private static final Shape NOTHING = new Shape(List.of(), List.of());
    private boolean solid = true;
    /** Told to become solid while a ball was in the way: it does as soon as the cell is clear. */
    private boolean waiting;
    /** The square it fills when solid, made once per placement: the board and the loop measure against it. */
    private Shape solidShape;

    SwitchedCell(String name, GizmoKind kind, int x, int y) {
        super(name, kind, x, y);
        rebuildShape();
    }

    SwitchedCell(SwitchedCell other) {
        super(other);
        this.solid = other.solid;
        this.waiting = other.waiting;
        this.solidShape = other.solidShape;
    }

    @Override
    public double reflectionCoefficient() {
        return 1.0;
    }

    /** Whether balls bounce off it now. For the board and its loop; views read their kind's own words. */
    public boolean isSolid() {
        return solid;
    }

    /** Opened while nothing (a gate open, a drop target down), waiting or not: loaded again, it is nothing. */
    @Override
    public final PlayState playState() {
        return solid ? new PlayState.AsBuilt() : new PlayState.Opened();
    }

    /**
     * Whether a ball's hit makes it nothing at the end of the tick (a drop target; a gate only opens when told). For
     * the board, not for views.
     */
    public abstract boolean fallsWhenHit();

    /** Whether it is nothing now only because a ball lies in its cell: it becomes solid once the cell is clear. */
    public boolean isWaiting() {
        return waiting;
    }

    @Override
    final Shape buildShape() {
        solidShape = Shape.polygon(cellOutline());
        return solid ? solidShape : NOTHING;
    }

    /** Signed distance to its solid body: its cell while solid, none (infinitely far) while nothing. */
    @Override
    public final double signedDistance(Vect p) {
        return solid ? solidOver(p) : Double.POSITIVE_INFINITY;
    }

    /**
     * Signed distance from p to the cell it fills when solid, solid now or not: the board asks it before making the
     * cell solid. For the board and its loop, not for views.
     */
    public final double solidOver(Vect p) {
        return Solids.toConvexPolygon(solidShape.segments(), p);
    }

    /**
     * Makes it solid or nothing (and rebuilds its shape), or, with {@code nowWaiting}, nothing until its cell is
     * clear. For the board and its loop, not for views.
     */
    public final void set(boolean nowSolid, boolean nowWaiting) {
        solid = nowSolid;
        waiting = nowWaiting;
        rebuildShape();
    }
}
