package gizmoball.model.gizmo;

import physics.Vect;

/**
 * A gizmo that adds a ball to the board when told (a spawner), as the board's play rules see it through
 * {@link Surroundings#spawn}: where the ball starts and how fast. The rules check the room there and the count
 * ({@link #MAX_BALLS}), not which kind asked.
 */
public interface BallSource {
    /** No ball is added to a board that holds this many. */
    int MAX_BALLS = 200;

    String name();

    /** Where the centre of a new ball of that radius starts: touching its mouth, mid-side. */
    Vect mouth(double ballRadius);

    /** The velocity a new ball starts with. */
    Vect velocity();
}
