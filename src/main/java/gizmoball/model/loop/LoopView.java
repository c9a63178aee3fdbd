package gizmoball.model.loop;

import java.util.Collection;
import java.util.List;

import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.MovingShape;

import physics.Vect;

/**
 * What the loop (a {@link TickRun} with its detector and contacts) sees of the board: the balls, gizmos, wiring and
 * constants it reads, and its own state that outlives a tick (the sleepers, the ball grid). It reads the board
 * through this and nothing else, as a pipeline stage of a physics engine reads its world; what play does back to
 * the board goes through {@link LoopActions} (docs/design.md, "The tick"). The board is the one implementation.
 */
public interface LoopView {
    /** Every ball, captured ones included, in board order (a list, so that the loop walks it by index). */
    List<Ball> balls();

    /** Every gizmo, in board order. */
    Collection<GizmoBase> gizmos();

    /** The named gizmo; null if there is none. */
    GizmoBase gizmo(String name);

    /** The named ball; null if there is none. */
    Ball ball(String name);

    /** The gizmos whose shapes move in play (the flippers), in board order. */
    List<MovingShape> movingShapes();

    /** The connections from {@code source}, in the order made. */
    List<Connection> connectionsFrom(TriggerSource source);

    /** The gizmos by cell, for what a ball can reach. */
    SpatialIndex index();

    /** False only in benchmarks and tests that scan every gizmo instead of asking the index. */
    boolean spatialIndexEnabled();

    /** The acceleration of gravity, L/s^2, as a vector on the board. */
    Vect gravity();

    double mu();

    double mu2();

    /** Seconds of play so far: the start of the tick being run. */
    double time();

    LoopMode loopMode();

    /** Whether the two balls were placed on each other and pass through until they are apart. */
    boolean passingThrough(Ball a, Ball b);

    /** How far ahead each tick's report looks for every ball's next collision (0: not at all). */
    double nextCollisionLookAhead();

    /** Whether each tick times its stages for its report (else every stage reads 0 and no clock is read). */
    boolean timesStages();

    /** How long the observers took to redraw after the previous tick. */
    long lastRedrawNanos();

    Sleepers sleepers();

    BallGrid ballGrid();
}
