package gizmoball.model.gizmo;

import java.util.List;

import physics.Vect;

/**
 * A gizmo whose solid body is one convex polygon that never changes in play: its shape and its signed distance both
 * come from its outline, so the two cannot disagree.
 */
abstract sealed class PolygonGizmo extends GizmoBase permits Absorber, Portal, Sink, Spawner {
    PolygonGizmo(String name, GizmoKind kind, int x, int y) {
        super(name, kind, x, y);
    }

    PolygonGizmo(PolygonGizmo other) {
        super(other);
    }

    /** Its body's corners in order round it; the sides between them are the segments of its shape. */
    abstract List<Vect> outline();

    @Override
    final Shape buildShape() {
        return Shape.polygon(outline());
    }

    @Override
    public final double signedDistance(Vect p) {
        return Solids.toConvexPolygon(shape().segments(), p);
    }
}
