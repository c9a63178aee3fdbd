package gizmoball.model.gizmo;

import java.util.List;

import physics.Vect;

/**
 * A 1x1 cell that takes every ball touching it out of play: the loop stops the ball at the sink's centre and the
 * board removes it once the tick is over. It reflects nothing and has no action but a flash.
 */
public final class Sink extends PolygonGizmo implements SinkView {

    Sink(String name, int x, int y) {
        super(name, GizmoKind.SINK, x, y);
        rebuildShape();
    }

    private Sink(Sink other) {
        super(other);
    }

    @Override
    public double reflectionCoefficient() {
        return 0;
    }

    /** A ball it takes stops at its centre, until the board removes it. For the board. */
    @Override
    public Vect take(String ball, double ballRadius) {
        return new Vect(x() + 0.5, y() + 0.5);
    }

    @Override
    List<Vect> outline() {
        return cellOutline();
    }

    @Override
    public Sink copy() {
        return new Sink(this);
    }
}
