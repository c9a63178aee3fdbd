package gizmoball.model.game;

import java.util.Optional;

/** What a game needs of the board it is played on, implemented by the board. */
public interface Playfield {

    GameRules rules();

    /** Seconds of play since the board was made: the board's clock. */
    double time();

    /** The balls on the board, free or held. */
    int ballCount();

    /** The balls on the board that no absorber holds. */
    int freeBallCount();

    /** Whether the absorber launches the game's balls: a drain or a plunger. */
    boolean isLauncher(String absorber);

    /** Takes a ball a drain captured off the board: the game has no ball to give in its place. */
    void removeBall(String ball);

    /**
     * Puts the next ball where the player launches it: in the first plunger of the board, else in the drain that holds
     * {@code drained} (which stays where it is), else in the first drain. The ball is {@code drained}, a ball a drain
     * holds, or a new one if empty (the last ball left the board through a sink). False if the board has no such
     * absorber.
     */
    boolean serve(Optional<String> drained);
}
