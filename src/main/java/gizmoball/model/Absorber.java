package gizmoball.model;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;

import physics.Vect;

/**
 * A rectangle of whole cells that captures every ball touching it, holds captured balls at its bottom-right
 * corner and, when triggered, fires the longest-held one straight up.
 */
public final class Absorber extends GizmoBase implements Gizmo {
    private final int width;
    private final int height;
    /** Names of the balls held, in capture order (names keep deep copies of the board simple). */
    private final Deque<String> held = new ArrayDeque<>();

    Absorber(String name, int x, int y, int width, int height) {
        super(name, GizmoKind.ABSORBER, x, y);
        this.width = width;
        this.height = height;
        rebuildShape();
    }

    private Absorber(Absorber other) {
        super(other);
        this.width = other.width;
        this.height = other.height;
        this.held.addAll(other.held);
    }

    @Override
    public int width() {
        return width;
    }

    @Override
    public int height() {
        return height;
    }

    @Override
    public double reflectionCoefficient() {
        return 0;
    }

    List<Vect> outline() {
        int x = x();
        int y = y();
        return List.of(new Vect(x, y), new Vect(x + width, y), new Vect(x + width, y + height), new Vect(x, y + height));
    }

    /** Where a captured ball's centre sits: the bottom-right corner, ball inside. */
    Vect holdingPosition() {
        return new Vect(x() + width - Board.BALL_RADIUS, y() + height - Board.BALL_RADIUS);
    }

    /** Where a fired ball starts: right above the top edge, touching it, in the holding column. */
    Vect launchPosition() {
        return new Vect(x() + width - Board.BALL_RADIUS, y() - Board.BALL_RADIUS);
    }

    Deque<String> held() {
        return held;
    }

    @Override
    Shape buildShape() {
        return Shape.polygon(outline());
    }

    @Override
    double signedDistance(Vect p) {
        return Solids.toConvexPolygon(outline(), p);
    }

    /** Fires the longest-held ball, if the spot above is free. */
    @Override
    void act(Play play) {
        play.fire(this);
    }

    @Override
    Absorber copy() {
        return new Absorber(this);
    }
}
