package gizmoball.model.game;

/** What a game needs of the board it is played on, implemented by the board. */
public interface Playfield {

    GameRules rules();

    /** The balls on the board, free or held. */
    int ballCount();

    /** Takes a ball a drain captured off the board: the game has no ball to give in its place. */
    void removeBall(String ball);

    /**
     * A sink took the ball in play and balls are still to come: the next one is put where a drained ball would
     * wait, held in the first drain that can hold it (an absorber). False if the board has none.
     */
    boolean serveNextBall();
}
