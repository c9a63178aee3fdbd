package gizmoball.model.gizmo;

import java.util.List;

import physics.Vect;

/**
 * A solid 1x1 cell that, when told to spawn, adds a ball at its mouth (the side it faces: up unturned, then right,
 * down, left with each quarter turn) with the velocity the author gave it, if the mouth is free and the board holds
 * fewer than {@link #MAX_BALLS} balls.
 */
public final class Spawner extends GizmoBase implements SpawnerView {
    /** A spawner adds no ball to a board that holds this many. */
    public static final int MAX_BALLS = 200;
    private Vect velocity = Vect.ZERO;

    Spawner(String name, int x, int y) {
        super(name, GizmoKind.SPAWNER, x, y);
        rebuildShape();
    }

    private Spawner(Spawner other) {
        super(other);
        this.velocity = other.velocity;
    }

    @Override
    public double reflectionCoefficient() {
        return 1.0;
    }

    @Override
    public Vect velocity() {
        return velocity;
    }

    /** The velocity of the balls it spawns (the board has checked it). For the board and its loop, not for views. */
    public void setVelocity(Vect newVelocity) {
        velocity = newVelocity;
    }

    @Override
    public Vect mouth(double ballRadius) {
        return rotated(x() + 0.5, y() - ballRadius);
    }

    private List<Vect> outline() {
        return List.of(new Vect(x(), y()), new Vect(x() + 1, y()), new Vect(x() + 1, y() + 1), new Vect(x(), y() + 1));
    }

    @Override
    Shape buildShape() {
        return Shape.polygon(outline());
    }

    @Override
    public double signedDistance(Vect p) {
        return Solids.toConvexPolygon(outline(), p);
    }

    /** Spawns a ball: the board checks the mouth and the count. */
    @Override
    public void perform(Action action, Surroundings around) {
        if (action == Action.SPAWN) {
            around.spawn(this);
        }
    }

    @Override
    public Spawner copy() {
        return new Spawner(this);
    }
}
