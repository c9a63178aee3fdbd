package gizmoball.bench;

import gizmoball.model.loop.LoopMode;

/** The stepping schemes compared: the model's two loops and the naive baseline. */
enum Loop {
    /** The model's seed loop: one move and at most one collision per tick. */
    SEED,
    /** The model's default loop: the whole tick simulated, several collisions per tick. */
    CONTINUOUS,
    /** The baseline people write first: move, then push overlapping balls out and reflect ({@link NaiveStepper}). */
    NAIVE;

    LoopMode modelMode() {
        if (this == NAIVE) {
            throw new IllegalStateException("the naive loop is the benchmark's own, not a model loop mode");
        }
        return LoopMode.valueOf(name());
    }
}
