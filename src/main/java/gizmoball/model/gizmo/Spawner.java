package gizmoball.model.gizmo;

import java.util.List;
import java.util.function.Function;

import physics.Vect;

/**
 * A solid 1x1 cell that, when told to spawn, adds a ball at its mouth (the side it faces: up unturned, then right,
 * down, left with each quarter turn) with the velocity the author gave it, if the mouth is free and the board holds
 * fewer than {@link #MAX_BALLS} balls.
 */
public final class Spawner extends PolygonGizmo implements SpawnerView, BallSource {
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

    @Override
    public Setting setting() {
        return new Setting.Launch(velocity.x(), velocity.y());
    }

    @Override
    public void hold(Setting setting, Function<String, GizmoBase> gizmos) {
        Setting.Launch launch = (Setting.Launch) setting;
        velocity = new Vect(launch.vx(), launch.vy());
    }

    @Override
    public Vect mouth(double ballRadius) {
        return rotated(x() + 0.5, y() - ballRadius);
    }

    @Override
    List<Vect> outline() {
        return cellOutline();
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
