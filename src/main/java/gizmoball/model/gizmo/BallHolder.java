package gizmoball.model.gizmo;

import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;

import physics.Vect;

/**
 * A gizmo that holds the balls it takes ({@link BallTaking#HOLDS}), in the order taken, and fires the longest-held
 * straight up when triggered (an absorber), as the board's edits, play and game see it: where a held ball sits, where
 * a fired one starts and, when it is a {@link Plunger}, the key that pulls it. The board asks whether a gizmo is one,
 * not which kind it is. For the board, not for views.
 */
public interface BallHolder {
    String name();

    /** The names of the balls it holds, longest-held first. */
    List<String> held();

    /** It no longer holds the ball named {@code ball} (fired, moved or deleted), if it did. */
    void letGo(String ball);

    /** Where the centre of a held ball of radius {@code ballRadius} sits. */
    Vect holdingPosition(double ballRadius);

    /** Where a fired ball of radius {@code ballRadius} starts: touching it from above. */
    Vect launchPosition(double ballRadius);

    /** How it launches when it is a plunger; empty when it fires at once. */
    Optional<Plunger> plunger();

    /** Records board time {@code time} as its last trigger. */
    void markTriggered(double time);

    /** The key pulling it, if one is. */
    OptionalInt pullingKey();

    /** The key starts to pull it, from no pull. */
    void startPull(int keyCode);

    /** The pulling key was held through a tick of {@code dt} seconds. */
    void heldFor(double dt);

    /** The speed its release fires at now, after the time the key was held (a plunger that is pulled). */
    double releaseSpeed();

    /** The pull is over, released or dropped. */
    void letGoOfPull();
}
