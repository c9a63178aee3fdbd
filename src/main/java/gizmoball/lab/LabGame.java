package gizmoball.lab;

import gizmoball.model.Board;
import java.util.concurrent.CancellationException;

/** One game of the lab: a player on its own copy of the board, to game over or the cap. */
final class LabGame {
    private LabGame() {
    }

    /**
     * Plays {@code board} (which the game makes its own: nobody else may use it) with a player of {@code kind}
     * drawing its chances from {@code seed}, counting where the balls went into {@code heat}.
     *
     * @throws CancellationException when {@code progress} says to stop
     */
    static GameResult play(Board board, PlayerKind kind, long seed, LabSettings settings, LabProgress progress,
                           HeatGrid heat) {
        Player player = kind.create(board, settings.dt(), seed);
        GameTally tally = new GameTally(board, settings.dt(), heat);
        long cap = board.ticks() + Math.max(1, Math.round(settings.gameCapSeconds() / settings.dt()));
        while (!board.game().isOver() && board.ticks() < cap) {
            if (progress.cancelled()) {
                throw new CancellationException("the lab was cancelled");
            }
            player.beforeTick(board);
            board.tick(settings.dt());
            tally.afterTick();
        }
        return tally.result();
    }
}
