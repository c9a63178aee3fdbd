package gizmoball.model.game;

import java.util.List;
import java.util.OptionalLong;

/** A game as views and reports read it; nothing here changes it. */
public interface GameProgress {

    /** False on a board with no drain, a sandbox: it scores, but has no balls to lose and never ends. */
    boolean isGame();

    long score();

    /** The balls on the board (in play or waiting in an absorber) and those still to come. */
    int ballsLeft();

    /** The last ball drained. */
    boolean isOver();

    /** The tick in which the extra ball was awarded, if it was. */
    OptionalLong extraBallTick();

    /** Every hit that scored, in order. */
    List<ScoringHit> scoringHits();

    /** Every ball lost, in order. */
    List<Drain> drains();

    /** Every key pressed and released on the board, in order, with its tick: the game's replay script. */
    List<KeyPress> keys();
}
