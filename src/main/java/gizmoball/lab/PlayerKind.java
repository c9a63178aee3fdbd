package gizmoball.lab;

import gizmoball.model.Board;
import java.util.Locale;
import java.util.SplittableRandom;

/** The players the lab compares: one that flips, and one that only launches, to tell what the flippers are worth. */
public enum PlayerKind {
    /** {@link AutoPlayer}: flips at the balls it can reach, with a reaction time and the odd mistake. */
    AUTOPLAYER,
    /** {@link IdlePlayer}: launches each ball and never flips. */
    IDLE;

    /** How reports name it: "autoplayer", "idle". */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** A player of this kind for {@code board}, ticks of {@code dt} seconds, its chances drawn from {@code seed}. */
    public Player create(Board board, double dt, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        return switch (this) {
            case AUTOPLAYER -> new AutoPlayer(board, dt, random);
            case IDLE -> new IdlePlayer(board, dt, random);
        };
    }
}
