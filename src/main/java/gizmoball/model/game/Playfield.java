package gizmoball.model.game;

/** What a game needs of the board it is played on, implemented by the board. */
public interface Playfield {

    GameRules rules();

    /** The balls on the board, free or held. */
    int ballCount();

    /** Takes a ball a drain captured off the board: the game has no ball to give in its place. */
    void removeBall(String ball);
}
