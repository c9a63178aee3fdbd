package gizmoball.model;

import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.MovingShape;
import gizmoball.model.gizmo.Order;
import gizmoball.model.loop.Ball;
import gizmoball.model.loop.BallGrid;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.LoopActions;
import gizmoball.model.loop.LoopMode;
import gizmoball.model.loop.LoopView;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.Sleepers;
import gizmoball.model.loop.SpatialIndex;
import gizmoball.model.loop.Struck;
import gizmoball.model.loop.TickEvents;
import gizmoball.model.loop.TickRun;
import gizmoball.model.loop.TriggerSource;

import java.util.Collection;
import java.util.List;

import physics.Vect;

/**
 * The board as the loop sees it and acts on it: the one way in for a {@link TickRun}, which may not use the model's
 * package. Each member hands the loop one of the board's parts or one of its numbers; the board keeps them. It also
 * keeps the loop's own switches, which only tests and the benchmark turn (through the board), and what the last
 * redraw cost, for the tick's report.
 */
final class BoardLoop implements LoopView, LoopActions {
    private final PhysicsConstants constants;
    private final Clock clock;
    private final Registry registry;
    private final Wiring wiring;
    private final Play play;
    private final Sleepers sleepers;
    private final EventLog events;
    private final EndOfTick endOfTick;
    /** Reused by every tick: the broad phase for ball pairs. */
    private final BallGrid ballGrid = new BallGrid();
    private boolean spatialIndexEnabled = true;
    private LoopMode loopMode = LoopMode.CONTINUOUS;
    private double nextCollisionLookAhead;
    private boolean timesStages;
    private long lastRedrawNanos;
    /** The last {@link #gravity()}, kept while the board's gravity stays the same (a vector is a value). */
    private Vect gravity;

    BoardLoop(PhysicsConstants constants, Clock clock, Registry registry, Wiring wiring, Play play,
            Sleepers sleepers, EventLog events, EndOfTick endOfTick) {
        this.constants = constants;
        this.clock = clock;
        this.registry = registry;
        this.wiring = wiring;
        this.play = play;
        this.sleepers = sleepers;
        this.events = events;
        this.endOfTick = endOfTick;
    }

    @Override
    public List<Ball> balls() {
        return registry.ballList();
    }

    @Override
    public Collection<GizmoBase> gizmos() {
        return registry.gizmos();
    }

    @Override
    public GizmoBase gizmo(String name) {
        return registry.gizmo(name);
    }

    @Override
    public Ball ball(String name) {
        return registry.ball(name);
    }

    @Override
    public List<MovingShape> movingShapes() {
        return registry.movingShapes();
    }

    @Override
    public List<Connection> connectionsFrom(TriggerSource source) {
        return wiring.connectionsFrom(source);
    }

    @Override
    public SpatialIndex index() {
        return registry.index();
    }

    @Override
    public boolean spatialIndexEnabled() {
        return spatialIndexEnabled;
    }

    void setSpatialIndexEnabled(boolean enabled) {
        spatialIndexEnabled = enabled;
    }

    @Override
    public Vect gravity() {
        double g = constants.gravity();
        if (gravity == null || gravity.y() != g) {
            gravity = new Vect(0, g);   // the board's gravity pulls down the board, along +y
        }
        return gravity;
    }

    @Override
    public double mu() {
        return constants.mu();
    }

    @Override
    public double mu2() {
        return constants.mu2();
    }

    @Override
    public double time() {
        return clock.time();
    }

    @Override
    public LoopMode loopMode() {
        return loopMode;
    }

    void setLoopMode(LoopMode mode) {
        if (mode == null) {
            throw new IllegalArgumentException("loop mode must not be null");
        }
        loopMode = mode;
    }

    @Override
    public boolean passingThrough(Ball a, Ball b) {
        return registry.passingThrough(a, b);
    }

    @Override
    public double nextCollisionLookAhead() {
        return nextCollisionLookAhead;
    }

    void setNextCollisionLookAhead(double seconds) {
        if (!(seconds >= 0) || Double.isInfinite(seconds)) {
            throw new IllegalArgumentException("look-ahead must be finite and not negative, got " + seconds);
        }
        nextCollisionLookAhead = seconds;
    }

    @Override
    public boolean timesStages() {
        return timesStages;
    }

    void setStageTiming(boolean on) {
        timesStages = on;
    }

    @Override
    public long lastRedrawNanos() {
        return lastRedrawNanos;
    }

    void setLastRedrawNanos(long nanos) {
        lastRedrawNanos = nanos;
    }

    @Override
    public Sleepers sleepers() {
        return sleepers;
    }

    @Override
    public BallGrid ballGrid() {
        return ballGrid;
    }

    @Override
    public void recordEvent(PlayEvent event) {
        events.record(event);
    }

    @Override
    public void recordHit(Ball ball, Struck struck, GizmoKind kind, double speed) {
        events.recordHit(ball, struck, kind, speed);
    }

    @Override
    public TickEvents closeTickEvents() {
        return events.closeTick();
    }

    @Override
    public void trigger(GizmoBase gizmo, Order order, double now) {
        play.carryOut(gizmo, order.action().orElse(gizmo.kind().defaultAction()), order.delay(), now);
    }

    @Override
    public void take(Ball ball, GizmoBase gizmo) {
        play.take(ball, gizmo);
    }

    @Override
    public void wakeSweep(MovingShape moving) {
        play.wakeSweep(moving);
    }

    @Override
    public void forgetSeparatedPairs() {
        registry.forgetSeparatedPairs();
    }

    @Override
    public void advanceTime(double dt) {
        clock.advance(dt);
        play.clockMoved();
    }

    /** The switches of {@code source}'s loop (a copy of a board plays as its original does). */
    void copySwitchesFrom(BoardLoop source) {
        loopMode = source.loopMode;
        spatialIndexEnabled = source.spatialIndexEnabled;
    }
}
