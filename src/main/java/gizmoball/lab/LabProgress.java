package gizmoball.lab;

/** What a lab run tells the one who started it, and asks them: how far it is, and whether to stop. */
public interface LabProgress {
    /** Told from the threads that play, after each game: {@code done} of {@code total} games are played. */
    void gamesDone(int done, int total);

    /** Asked often while games play: true stops the run within a tick of a game. */
    default boolean cancelled() {
        return false;
    }

    /** Tells nothing and never stops. */
    LabProgress NONE = (done, total) -> { };
}
