package gizmoball.lab;

import gizmoball.model.Board;

/**
 * How the lab plays a board.
 *
 * @param games          games for each player
 * @param threads        threads playing at once (at least 1); the results do not depend on it
 * @param gameCapSeconds game time after which a game that is not over ends (a sandbox never is)
 * @param dt             seconds of each tick
 */
public record LabSettings(int games, int threads, double gameCapSeconds, double dt) {
    /** Ten minutes of play: far longer than a game on a table that drains, and an end for a sandbox. */
    public static final double DEFAULT_GAME_CAP_SECONDS = 600;

    public LabSettings {
        if (games < 1) {
            throw new IllegalArgumentException("the lab needs at least one game, not " + games);
        }
        if (threads < 1) {
            throw new IllegalArgumentException("the lab needs at least one thread, not " + threads);
        }
        if (!(gameCapSeconds > 0) || Double.isInfinite(gameCapSeconds)) {
            throw new IllegalArgumentException("the game cap must be a number of seconds > 0, not " + gameCapSeconds);
        }
        if (!(dt > 0) || Double.isInfinite(dt)) {
            throw new IllegalArgumentException("the tick must be a number of seconds > 0, not " + dt);
        }
    }

    /** {@code games} games each on every core, with the default cap and tick. */
    public static LabSettings of(int games) {
        return new LabSettings(games, Runtime.getRuntime().availableProcessors(), DEFAULT_GAME_CAP_SECONDS,
                Board.DEFAULT_TICK);
    }

    public LabSettings withThreads(int count) {
        return new LabSettings(games, count, gameCapSeconds, dt);
    }

    public LabSettings withGameCap(double seconds) {
        return new LabSettings(games, threads, seconds, dt);
    }
}
