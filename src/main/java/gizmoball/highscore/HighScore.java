package gizmoball.highscore;

import gizmoball.replay.Replay;
import java.time.LocalDate;

/** One entry of a board's table: who, how many points, when, and the game itself, to watch again. */
public record HighScore(String name, long score, LocalDate date, Replay replay) {
    /** Names longer than this are cut: the table is for reading at a glance. */
    public static final int MAX_NAME = 24;

    public HighScore {
        name = name.strip();
        if (name.isEmpty()) {
            throw new IllegalArgumentException("a high score needs a name");
        }
        if (name.length() > MAX_NAME) {
            name = name.substring(0, MAX_NAME);
        }
    }
}
