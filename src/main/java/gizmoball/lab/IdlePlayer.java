package gizmoball.lab;

import gizmoball.model.Board;
import java.util.SplittableRandom;

/** A player who launches each ball and never touches a flipper: what the table does on its own. */
public final class IdlePlayer implements Player {
    private final Launcher launcher;

    /** For {@code board}, played in ticks of {@code dt} seconds. */
    public IdlePlayer(Board board, double dt, SplittableRandom random) {
        launcher = new Launcher(board, dt, random);
    }

    @Override
    public void beforeTick(Board board) {
        launcher.beforeTick(board);
    }
}
