package gizmoball.model.gizmo;

import java.util.List;

import physics.Circle;
import physics.Vect;

/** A square, circle or triangle bumper: reflects with coefficient 1.0, has no action of its own. */
public final class Bumper extends GizmoBase implements BumperView {
    static final double CIRCLE_RADIUS = 0.5;

    Bumper(GizmoKind kind, String name, int x, int y) {
        super(name, kind, x, y);
        if (kind != GizmoKind.SQUARE && kind != GizmoKind.CIRCLE && kind != GizmoKind.TRIANGLE) {
            throw new IllegalArgumentException(kind.withArticle() + " is not a bumper");
        }
        rebuildShape();
    }

    private Bumper(Bumper other) {
        super(other);
    }

    @Override
    public double reflectionCoefficient() {
        return 1.0;
    }

    /** Polygon corners in board coordinates in the current rotation (square 4, triangle 3); empty for a circle. */
    public List<Vect> outline() {
        int x = x();
        int y = y();
        return switch (kind()) {
            case SQUARE -> cellOutline();
            case TRIANGLE -> List.of(rotated(x, y), rotated(x + 1, y), rotated(x, y + 1));
            default -> List.of();
        };
    }

    /** The circle of a CIRCLE bumper: centred in its cell, radius 0.5. */
    public Circle circle() {
        if (kind() != GizmoKind.CIRCLE) {
            throw new IllegalStateException(name() + " is " + kind().withArticle() + ", not a circle");
        }
        return new Circle(x() + 0.5, y() + 0.5, CIRCLE_RADIUS);
    }

    @Override
    Shape buildShape() {
        return kind() == GizmoKind.CIRCLE ? Shape.circle(circle()) : Shape.polygon(outline());
    }

    @Override
    public double signedDistance(Vect p) {
        return kind() == GizmoKind.CIRCLE
                ? Solids.toDisc(circle().getCenter(), CIRCLE_RADIUS, p)
                : Solids.toConvexPolygon(shape().segments(), p);
    }

    @Override
    public Bumper copy() {
        return new Bumper(this);
    }
}
