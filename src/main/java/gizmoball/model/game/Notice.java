package gizmoball.model.game;

/** Something the game tells the player, in the tick numbered {@code tick}, about {@code player} (0 for the first). */
public record Notice(long tick, Kind kind, int player) {

    public enum Kind {
        /** One more nudge within the tilt's time would tilt. */
        WARNING,
        /** Nudged too often: flippers and plungers dead, the ball scores nothing more until it drains. */
        TILT,
        /** The ball drained soon after its launch and is given back. */
        BALL_SAVED,
        /** The player reached the extra-ball score: one more ball. */
        EXTRA_BALL,
        /** The ball was lost and it is this player's turn. */
        NEXT_PLAYER
    }
}
