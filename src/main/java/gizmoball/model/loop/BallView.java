package gizmoball.model.loop;

import physics.Vect;

/**
 * What views, controllers and the editor see of a ball, read only: {@code Board.balls()} hands out balls as this,
 * so only the board and its loop reach {@link Ball}'s mutators.
 */
public sealed interface BallView permits Ball {
    String name();

    /** Centre in L. */
    Vect position();

    /** Velocity in L/s. */
    Vect velocity();

    double radius();

    /** True while an absorber holds it. */
    boolean isCaptured();

    /** True while the ball lies still in contact and the loop leaves it alone until something can reach it. */
    boolean isAsleep();
}
