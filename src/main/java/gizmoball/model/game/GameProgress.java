package gizmoball.model.game;

import java.util.List;
import java.util.OptionalLong;

/** A game as views and reports read it; nothing here changes it. */
public interface GameProgress {

    /** False on a board with no drain, a sandbox: it scores, but has no balls to lose and never ends. */
    boolean isGame();

    /** How many take turns, 1 to {@link Game#MAX_PLAYERS}. */
    int players();

    /** Whose ball is in play: 0 for the first player. */
    int currentPlayer();

    /** Every player's score together (a game of one player: the score). */
    long score();

    /** The score of a player, 0 for the first. */
    long score(int player);

    /** The balls on the board (in play or waiting in an absorber) and those still to come, for every player. */
    int ballsLeft();

    /** The balls a player has still to play, the one in play counted for its player. */
    int ballsLeft(int player);

    /** Nudged too often: the flippers and plungers are dead and the ball scores nothing until it drains. */
    boolean isTilted();

    /** What the game told the player (warnings, tilts, balls saved, extra balls, turns), in order. */
    List<Notice> notices();

    /** The last ball drained. */
    boolean isOver();

    /** The tick in which the first extra ball was awarded, if one was. */
    OptionalLong extraBallTick();

    /** Every hit that scored, in order, up to {@link Game#LISTED_SCORING_HITS}: the first ones. */
    List<ScoringHit> scoringHits();

    /** The hits that scored after the first {@link Game#LISTED_SCORING_HITS}: counted, not listed. */
    long unlistedScoringHits();

    /** Every ball lost, in order. */
    List<Drain> drains();

    /** Every key pressed and released on the board, in order, with its tick: the game's replay script. */
    List<KeyPress> keys();
}
