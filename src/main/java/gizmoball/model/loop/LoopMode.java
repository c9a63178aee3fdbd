package gizmoball.model.loop;

/**
 * How a {@link TickRun} spends a tick. SEED is the classic loop: one move and at most one collision per
 * tick (the time after that collision is lost). CONTINUOUS simulates the whole tick: after each collision,
 * detection and resolution repeat until the tick is used up.
 */
public enum LoopMode { SEED, CONTINUOUS }
