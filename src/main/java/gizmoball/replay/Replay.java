package gizmoball.replay;

import gizmoball.boardfile.BoardFileException;
import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.game.Game;

/**
 * A game as a replay file holds it: the board as built (board-file text), the tick length, how many ticks the game
 * ran, every key pressed and released with its tick, the score it reached (every player's together) and how many
 * players took turns.
 */
public record Replay(String board, double dt, long ticks, KeyScript keys, long score, int players) {

    public Replay {
        if (!(dt > 0) || Double.isInfinite(dt)) {
            throw new IllegalArgumentException("a replay's tick is a number of seconds > 0, not " + dt);
        }
        if (players < 1 || players > Game.MAX_PLAYERS) {
            throw new IllegalArgumentException("a replay is of a game for 1 to " + Game.MAX_PLAYERS + " players, not "
                    + players);
        }
        if (ticks < 0) {
            throw new IllegalArgumentException("a replay runs 0 ticks or more, not " + ticks);
        }
    }

    /** The game played on {@code played}, which started as {@code boardAsBuilt} and ticked {@code dt} each time. */
    public static Replay of(String boardAsBuilt, Board played, double dt) {
        return new Replay(boardAsBuilt, dt, played.ticks(), new KeyScript(played.game().keys()), played.game().score(),
                played.game().players());
    }

    /** The board as built, loaded afresh, at tick 0, its game for the replay's players. */
    public Board boardAsBuilt(String source) throws BoardFileException {
        Board built = BoardFiles.load(source, board);
        built.setPlayers(players);
        return built;
    }

    /** The game played again from the board as built: the board as it is at the replay's last tick. */
    public Board replayed(String source) throws BoardFileException {
        return ScriptedPlay.play(boardAsBuilt(source), keys, ticks, dt);
    }
}
