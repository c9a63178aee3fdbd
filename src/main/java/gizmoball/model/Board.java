package gizmoball.model;

import gizmoball.model.game.Game;
import gizmoball.model.game.GameProgress;
import gizmoball.model.game.GameRules;
import gizmoball.model.game.Nudge;
import gizmoball.model.game.Tilt;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.loop.Arena;
import gizmoball.model.loop.Ball;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.GuardCounts;
import gizmoball.model.loop.LoopActions;
import gizmoball.model.loop.LoopMode;
import gizmoball.model.loop.LoopSettings;
import gizmoball.model.loop.LoopView;
import gizmoball.model.loop.Sleepers;
import gizmoball.model.loop.TickReport;
import gizmoball.model.loop.TickRun;
import gizmoball.model.loop.TriggerSource;

import java.util.Collection;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;

/**
 * The game board: gizmos, balls, connections, key bindings and the physics constants, with the editing operations
 * (each succeeds completely or throws {@link BoardEditException} and changes nothing), queries, and play
 * ({@link #tick(double)}, keys, triggers). It is the facade over parts with one job each: the {@link Registry} of
 * gizmos and balls, the {@link PlacementRules}, the {@link Edits} of gizmos and balls, the {@link Wiring} of
 * connections and keys, the actions of {@link Play} and the {@link Observers}; the physics loop itself is
 * {@link TickRun}, in a package of its own that may not use this one: it sees the board only through
 * {@link LoopView} and acts on it only through {@link LoopActions}, both implemented by {@link BoardLoop}.
 *
 * <p>Over 400 lines only because it is the model's whole public API, documented: each method delegates to a part
 * (also {@link PhysicsConstants}, {@link Clock}, {@link GameSettings}, {@link KeyPresses}, {@link TickCycle}, the
 * game's {@link GameField}).
 */
public final class Board {
    /** The side of the board in L and cells: the loop's {@link Arena#SIZE}, named here for the board's users (its
     *  own parts read {@link Arena}'s). */
    public static final int SIZE = Arena.SIZE;
    /** L: {@link Arena#BALL_RADIUS}. */
    public static final double BALL_RADIUS = Arena.BALL_RADIUS;
    /** L/s: {@link Arena#MAX_SPEED}. */
    public static final double MAX_SPEED = Arena.MAX_SPEED;
    public static final double DEFAULT_GRAVITY = 25;
    public static final double DEFAULT_MU = 0.025;
    public static final double DEFAULT_MU2 = 0.025;
    public static final double DEFAULT_TICK = 1.0 / 60;
    public static final double ABSORBER_LAUNCH_SPEED = 50;

    private final Registry registry = new Registry();
    private final PlacementRules rules = new PlacementRules(registry);
    private final Wiring wiring = new Wiring(registry);
    private final Sleepers sleepers = new Sleepers(registry.balls());
    private final EventLog events = new EventLog();
    private final EndOfTick endOfTick = new EndOfTick(registry, sleepers);
    private final DelayedActions delayed = new DelayedActions(registry);
    private final Play play = new Play(registry, rules, sleepers, events, endOfTick, delayed);
    private final Edits edits = new Edits(registry, rules, wiring, play);
    private final Observers observers = new Observers();
    private final PhysicsConstants constants = new PhysicsConstants();
    private final Clock clock = new Clock();
    private final GameSettings settings = new GameSettings();
    private final Game game = new Game(new GameField(settings, clock, registry, play));
    private final KeyPresses keys = new KeyPresses(registry, wiring, play, sleepers, settings, clock, game);
    private final BoardLoop loop = new BoardLoop(constants, clock, registry, wiring, play, sleepers, events,
            endOfTick);
    /** Every board's loop runs with the standard tuning, handed to it here. */
    private final TickCycle ticking = new TickCycle(play, endOfTick, delayed, clock, game, loop,
            LoopSettings.STANDARD);
    private final Runnable redraw = () -> notifyObservers(BoardChange.TICK);   // made once, not every tick

    /** A deep copy of the contents and play state (not the observers). */
    public Board copy() {
        Board copy = new Board();
        copy.copyStateFrom(this);
        return copy;
    }

    /** Becomes a deep copy of source (keeping its own observers) and notifies REPLACE. */
    public void replaceContents(Board source) {
        if (source != this) {
            copyStateFrom(source);
        }
        notifyObservers(BoardChange.REPLACE);
    }

    private void copyStateFrom(Board source) {
        registry.copyFrom(source.registry);
        wiring.copyFrom(source.wiring);
        constants.copyFrom(source.constants);
        clock.copyFrom(source.clock);
        play.clockMoved();
        delayed.copyFrom(source.delayed);
        settings.copyFrom(source.settings);
        game.copyFrom(source.game);
        loop.copySwitchesFrom(source.loop);
    }

    // ---------------------------------------------------------------- editing

    public void addGizmo(GizmoKind kind, String name, int x, int y) {
        edit(() -> edits.addGizmo(kind, name, x, y));
    }

    /** Adds an absorber covering the cells from (x1, y1) to the exclusive corner (x2, y2). */
    public void addAbsorber(String name, int x1, int y1, int x2, int y2) {
        edit(() -> edits.addAbsorber(name, x1, y1, x2, y2));
    }

    /**
     * Adds a ball (centre, velocity). The centre must be inside the board with the radius, the ball must not
     * overlap another free ball or a gizmo other than an absorber; one placed overlapping an absorber is captured.
     */
    public void addBall(String name, double x, double y, double vx, double vy) {
        edit(() -> edits.addBall(name, x, y, vx, vy));
    }

    /**
     * As {@link #addBall}, except that other free balls in the way do not refuse it (board files of other
     * implementations place balls on each other; the loop lets such a pair pass through until it separates).
     * Every other check stays. Returns the free balls it overlaps, in board order (none if it is captured).
     */
    public List<String> addBallOverlappingBalls(String name, double x, double y, double vx, double vy) {
        List<String> overlapped = edits.addBallOverlappingBalls(name, x, y, vx, vy);
        edited();
        return overlapped;
    }

    /**
     * Puts a flipper where play left it (a board saved during play): {@code degrees} from rest (0 to 90), swinging
     * toward its active stop when {@code active}, else toward rest; no free ball may be inside it there.
     */
    public void setFlipperState(String flipper, double degrees, boolean active) {
        edit(() -> edits.setFlipperState(flipper, degrees, active));
    }

    /** Turns a gizmo 90 degrees clockwise within its footprint; circles and absorbers stay as they are. */
    public void rotate(String gizmo) {
        edit(() -> edits.rotate(gizmo));
    }

    /** Deletes a ball or a gizmo (with its connections and keys; an absorber takes the balls it holds with it). */
    public void delete(String name) {
        edits.delete(name);
        settings.forget(name);
        edited();
    }

    /** Moves a gizmo to a new top-left cell, with the same checks as adding it there. */
    public void moveGizmo(String gizmo, int x, int y) {
        edit(() -> edits.moveGizmo(gizmo, x, y));
    }

    /**
     * Moves gizmos (by whole cells, an absorber with the balls it holds) and balls together by (dx, dy) L, as one
     * edit: each must fit where it goes with the others moved too (a row moves along itself), or nothing moves.
     */
    public void moveGroup(Collection<String> names, double dx, double dy) {
        edit(() -> edits.moveGroup(names, dx, dy));
    }

    /**
     * Gives an absorber new corners ((x2, y2) exclusive, as {@link #addAbsorber}) with the same checks as adding it
     * there; it keeps its name, place in board order, colour, connections, keys, points and the balls it holds.
     */
    public void resizeAbsorber(String absorber, int x1, int y1, int x2, int y2) {
        edit(() -> edits.resizeAbsorber(absorber, x1, y1, x2, y2));
    }

    /** Moves a ball's centre, with the same checks as adding it there; its velocity is kept unless captured. */
    public void moveBall(String ball, double x, double y) {
        edit(() -> edits.moveBall(ball, x, y));
    }

    /**
     * Gives a ball a new velocity, keeping its place in the board's order of balls (and so in a saved file); a ball
     * an absorber holds has no velocity of its own: only zero is accepted for it.
     */
    public void setBallVelocity(String ball, double vx, double vy) {
        if (edits.setBallVelocity(ball, vx, vy)) {
            edited();
        }
    }

    /** Whenever source (a gizmo or the outer walls) is hit, target performs its action. Self-connections allowed. */
    public void connect(TriggerSource source, String target) {
        connect(source, target, Order.DEFAULT);
    }

    /** Whenever source is hit, target does as {@code order} says: one of its kind's actions, after a delay. */
    public void connect(TriggerSource source, String target, Order order) {
        edit(() -> wiring.connect(source, target, order));
    }

    public void disconnect(TriggerSource source, String target) {
        edit(() -> wiring.disconnect(source, target));
    }

    /** The key's edge drives the gizmo as that edge does unless told ({@link KeyEdge#actionOf}), at once. */
    public void bindKey(int keyCode, KeyEdge edge, String gizmo) {
        bindKey(keyCode, edge, gizmo, Order.DEFAULT);
    }

    /** The key's edge drives the gizmo as {@code order} says: one of its kind's actions, after a delay. */
    public void bindKey(int keyCode, KeyEdge edge, String gizmo, Order order) {
        settings.requireNotNudging(keyCode);
        wiring.bindKey(keyCode, edge, gizmo, order);
        edited();
    }

    public void unbindKey(int keyCode, KeyEdge edge, String gizmo) {
        edit(() -> wiring.unbindKey(keyCode, edge, gizmo));
    }

    /** Gives a gizmo its own colour, or with empty back the colour of its kind. */
    public void setColour(String gizmo, Optional<Rgb> colour) {
        edit(() -> edits.setColour(gizmo, colour));
    }

    /**
     * Gives a gizmo the value its kind holds beyond its place (an accelerator's factor, a spawner's velocity, a
     * spinner's speed, a portal's pair: {@link Setting}), checked by the setting itself.
     */
    public void set(String gizmo, Setting setting) {
        edit(() -> edits.set(gizmo, setting));
    }

    /** Opens a gate or puts a drop target down, as play left it (a board saved during play), until it closes. */
    public void setCellOpen(String cell) {
        edit(() -> edits.setCellOpen(cell));
    }

    /**
     * Puts a spinner where play left it (a board saved during play): its bar at {@code radians} (from +x toward +y),
     * turning or stopped; no free ball may be inside the bar there.
     */
    public void setSpinnerState(String spinner, double radians, boolean running) {
        edit(() -> edits.setSpinnerState(spinner, radians, running));
    }

    public void setGravity(double g) {
        edit(() -> constants.setGravity(g));
    }

    public void setFriction(double newMu, double newMu2) {
        edit(() -> constants.setFriction(newMu, newMu2));
    }

    /** Removes everything, puts gravity and friction back to their defaults and the time to 0. */
    public void clear() {
        registry.clear();
        wiring.clear();
        constants.reset();
        clock.reset();
        play.clockMoved();
        delayed.clear();
        settings.reset();
        game.reset();
        notifyObservers(BoardChange.REPLACE);
    }

    // ---------------------------------------------------------------- the game (docs/design.md, "The game")

    /** How many balls a game has (1 to {@link GameRules#MAX_BALLS}; three until said otherwise). */
    public void setBallsPerGame(int balls) {
        edit(() -> settings.setBallsPerGame(balls));
    }

    /** Makes an absorber a drain (a ball it captures is lost) or an ordinary absorber again. */
    public void setDrain(String absorber, boolean drain) {
        edit(() -> settings.setDrain(registry.requireGizmo(absorber), drain));
    }

    /** What a real hit on the gizmo scores (its kind's value unless set; within plus or minus a million). */
    public void setPoints(String gizmo, int points) {
        edit(() -> settings.setPoints(gizmo, registry.requireGizmo(gizmo).kind(), points));
    }

    /** The score at which a game gives one extra ball, once; empty for none. */
    public void setExtraBallAt(OptionalLong score) {
        edit(() -> settings.setExtraBallAt(score));
    }

    /** Lets the board be nudged with the nudge's keys (which may drive nothing else), or with empty not at all. */
    public void setNudge(Optional<Nudge> nudge) {
        edit(() -> settings.setNudge(nudge, wiring.keyBindings()));
    }

    /** When nudging tilts the game (with a nudge: the board's {@link Tilt}, 4 nudges within 5 s unless set). */
    public void setTilt(Tilt tilt) {
        edit(() -> settings.setTilt(tilt));
    }

    /** For how many seconds after a launch a drained ball is given back, once (0: never, the default). */
    public void setBallSave(double seconds) {
        edit(() -> settings.setBallSave(seconds));
    }

    /**
     * A new game on this board is for that many players (1 to {@link Game#MAX_PLAYERS}, taking turns ball by ball),
     * chosen before its first tick; a board made or reset has a game for as many as it had.
     */
    public void setPlayers(int players) {
        if (clock.ticks() > 0) {
            throw new IllegalStateException("the number of players is chosen before the first tick");
        }
        game.setPlayers(players);
    }

    public GameRules gameRules() {
        return settings.rules();
    }

    /** The game on this board: score, balls left, drains, game over (a sandbox scores too). */
    public GameProgress game() {
        return game;
    }

    /** Ticks run since the board was made or cleared: the clock of games, key scripts and replays. */
    public long ticks() {
        return clock.ticks();
    }

    /**
     * Why a gizmo of that kind and footprint cannot have its top-left cell at (x, y), ignoring the gizmo named
     * {@code ignoring} (may be null), or empty if it can. Checks the board edges, other gizmos and balls.
     */
    public Optional<String> placementProblem(GizmoKind kind, int x, int y, int width, int height, String ignoring) {
        return rules.placementProblem(kind, x, y, width, height, ignoring);
    }

    // ---------------------------------------------------------------- queries

    public List<Gizmo> gizmos() {
        return registry.gizmos().stream().map(Gizmo.class::cast).toList();
    }

    public Optional<Gizmo> gizmo(String name) {
        return Optional.ofNullable(registry.gizmo(name)).map(Gizmo.class::cast);
    }

    public Optional<Gizmo> gizmoAt(int cx, int cy) {
        return Optional.ofNullable(registry.index().at(cx, cy)).map(Gizmo.class::cast);
    }

    /** The balls in board order, read only: the board and its loop change them. */
    public List<BallView> balls() {
        return List.copyOf(registry.balls());
    }

    public Optional<BallView> ball(String name) {
        return Optional.ofNullable(registry.ball(name));
    }

    public List<Connection> connections() {
        return wiring.connections();
    }

    public List<KeyBinding> keyBindings() {
        return wiring.keyBindings();
    }

    public double gravity() {
        return constants.gravity();
    }

    public double mu() {
        return constants.mu();
    }

    public double mu2() {
        return constants.mu2();
    }

    /** Simulated seconds since construction or {@link #clear()}. */
    public double time() {
        return clock.time();
    }

    // ---------------------------------------------------------------- play

    /** One tick of the six-stage loop (docs/design.md, "The tick"); dt in seconds, finite and not negative. */
    public void tick(double dt) {
        if (!Double.isFinite(dt) || dt < 0) {
            throw new IllegalArgumentException("tick length must be finite and not negative, got " + dt);
        }
        ticking.run(dt, redraw);
    }

    /** What the last tick did (stage times, collisions, balls awake, events); {@link TickReport#NONE} before any. */
    public TickReport lastTick() {
        return ticking.lastTick();
    }

    /** How often each last-resort guard of the loop has fired since this board was made. */
    public GuardCounts guardsFired() {
        return ticking.guardsFired();
    }

    /**
     * How far ahead, in seconds, each tick's report looks for every ball's next collision (0, the default: not at
     * all); the physics overlay turns it on, at a detection pass per ball and tick.
     */
    public void setNextCollisionLookAhead(double seconds) {
        loop.setNextCollisionLookAhead(seconds);
    }

    /**
     * Whether each tick times its stages for its report (off, the default: each reads 0, and no clock is read; read at
     * every collision, they cost a tick of 200 balls 1-3%). The physics overlay turns it on.
     */
    public void setStageTiming(boolean on) {
        loop.setStageTiming(on);
    }

    /**
     * Performs the actions bound to (keyCode, DOWN): flippers swing up, others act; and those bound to (keyCode,
     * CHANGE): a flipper toggles, others act. The game records the key ({@link GameProgress#keys()}), as every release.
     */
    public void keyDown(int keyCode) {
        keys.key(keyCode, KeyEdge.DOWN);
    }

    /** Performs the actions bound to (keyCode, UP): flippers swing back down, others perform their action. */
    public void keyUp(int keyCode) {
        keys.key(keyCode, KeyEdge.UP);
    }

    /** The gizmo performs its action: a flipper toggles, an absorber fires, a bumper only records the time. */
    public void trigger(String gizmo) {
        play.trigger(gizmo, clock.time());
    }

    public void addObserver(BoardObserver observer) {
        observers.add(observer);
    }

    public void removeObserver(BoardObserver observer) {
        observers.remove(observer);
    }

    /** Makes the change (which throws, changing nothing, if refused), then tells what {@link #edited} does. */
    private void edit(Runnable change) {
        change.run();
        edited();
    }

    /** After every successful edit: the board changed under the balls, which forget their contacts and wake. */
    private void edited() {
        sleepers.disturbAll();
        notifyObservers(BoardChange.EDIT);
    }

    private void notifyObservers(BoardChange change) {
        observers.tell(this, change);
    }

    // ---------------------------------------------------------------- for tests and the benchmark
    // The game always plays CONTINUOUS with the index: only tests (directly or through their LoopModes fixture) and
    // the benchmark (through BenchSwitches, in its own source set) turn these, so they are not public.

    void setLoopMode(LoopMode mode) {
        loop.setLoopMode(mode);
    }

    /** True (default): collision detection asks the grid for reachable gizmos; false: it scans every gizmo. */
    void setSpatialIndexEnabled(boolean enabled) {
        loop.setSpatialIndexEnabled(enabled);
    }

    /** Sum over free balls of |v|^2/2 + gravity * (SIZE - y), unit mass. */
    public double energy() {
        return registry.energy(constants.gravity());
    }

    // ---------------------------------------------------------------- for the invariants and the loop's tests

    Collection<GizmoBase> gizmoBases() {
        return registry.gizmos();
    }

    Collection<Ball> ballStates() {
        return registry.balls();
    }

    /** The loop's view of this board, for the loop's tests (through their fixture {@code LoopViews}) and loop mode. */
    LoopView loopView() {
        return loop;
    }
}
