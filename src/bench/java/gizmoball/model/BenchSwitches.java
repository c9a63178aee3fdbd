package gizmoball.model;

import gizmoball.model.loop.LoopMode;

/**
 * The benchmark's switches of the model's loop: the classic {@link LoopMode#SEED} loop, and a scan of every gizmo
 * instead of the spatial index, so that it can measure what the continuous loop and the index buy. The game never
 * turns them, so {@link Board} keeps them package-private; this class sits in the model's package but in the
 * benchmark's own source set, so the seam never reaches the game's classpath.
 */
public final class BenchSwitches {
    private BenchSwitches() {
    }

    public static void configure(Board board, LoopMode mode, boolean spatialIndex) {
        board.setLoopMode(mode);
        board.setSpatialIndexEnabled(spatialIndex);
    }
}
