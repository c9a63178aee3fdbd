package gizmoball.model;

import gizmoball.model.game.Game;
import gizmoball.model.game.GameProgress;
import gizmoball.model.game.GameRules;
import gizmoball.model.game.KeyPress;
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
import gizmoball.model.loop.LoopView;
import gizmoball.model.loop.Sleepers;
import gizmoball.model.loop.TickReport;
import gizmoball.model.loop.TickRun;
import gizmoball.model.loop.TriggerSource;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.function.Supplier;

import physics.Vect;

/**
 * The game board: gizmos, balls, connections, key bindings and the physics constants, with the editing operations
 * (each succeeds completely or throws {@link BoardEditException} and changes nothing), queries, and play
 * ({@link #tick(double)}, keys, triggers). It is the facade over parts with one job each: the {@link Registry} of
 * gizmos and balls, the {@link PlacementRules}, the {@link Edits} of gizmos and balls, the {@link Wiring} of
 * connections and keys, the actions of {@link Play} and the {@link Observers}; the physics loop itself is
 * {@link TickRun}, in a package of its own that may not use this one: it sees the board only through
 * {@link LoopView} and acts on it only through {@link LoopActions}, both implemented by {@link BoardLoop}.
 *
 * <p>It is over 400 lines only because it is the model's whole public API: every method is an argument check, a
 * delegation, or a constant of play (gravity, friction, time); the loop's adapter ({@link BoardLoop}) and the game's
 * ({@link GameField}) are classes of their own.
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
    private final Play play = new Play(registry, rules, sleepers);
    private final Edits edits = new Edits(registry, rules, wiring, play);
    private final Observers observers = new Observers();
    private double gravity = DEFAULT_GRAVITY;
    private double mu = DEFAULT_MU;
    private double mu2 = DEFAULT_MU2;
    private double time;
    /** Ticks run since construction or {@link #clear()}: the clock games, key scripts and replays count in. */
    private long ticks;
    private GameRules gameRules = GameRules.DEFAULT;
    private final Game game = new Game(new GameField(this, registry, play));
    private boolean spatialIndexEnabled = true;
    private LoopMode loopMode = LoopMode.CONTINUOUS;
    private TickReport lastTick = TickReport.NONE;
    private GuardCounts guardsFired = GuardCounts.NONE;
    private long lastRedrawNanos;
    private double nextCollisionLookAhead;
    private final BoardLoop loop = new BoardLoop(this, registry, wiring, play, sleepers);
    /** The loop, kept with its books from tick to tick. */
    private final TickRun tickRun = new TickRun(loop, loop);

    /** An empty board with default gravity and friction at time 0. */
    public Board() {
    }

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
        gravity = source.gravity;
        mu = source.mu;
        mu2 = source.mu2;
        time = source.time;
        play.clockMoved();
        play.copyDelayedFrom(source.play);
        ticks = source.ticks;
        gameRules = source.gameRules;
        game.copyFrom(source.game);
        loopMode = source.loopMode;
        spatialIndexEnabled = source.spatialIndexEnabled;
    }

    // ---------------------------------------------------------------- editing

    public void addGizmo(GizmoKind kind, String name, int x, int y) {
        edits.addGizmo(kind, name, x, y);
        edited();
    }

    /** Adds an absorber covering the cells from (x1, y1) to the exclusive corner (x2, y2). */
    public void addAbsorber(String name, int x1, int y1, int x2, int y2) {
        edits.addAbsorber(name, x1, y1, x2, y2);
        edited();
    }

    /**
     * Adds a ball (centre, velocity). The centre must be inside the board with the radius, the ball must not
     * overlap another free ball or a gizmo other than an absorber; one placed overlapping an absorber is captured.
     */
    public void addBall(String name, double x, double y, double vx, double vy) {
        edits.addBall(name, x, y, vx, vy);
        edited();
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
     * Puts a flipper where play left it: {@code degrees} from rest (0 to 90), swinging toward its active stop when
     * {@code active}, else toward rest. A board saved during play keeps its flippers this way; no free ball may be
     * inside the flipper there.
     */
    public void setFlipperState(String flipper, double degrees, boolean active) {
        edits.setFlipperState(flipper, degrees, active);
        edited();
    }

    /** Turns a gizmo 90 degrees clockwise within its footprint; circles and absorbers stay as they are. */
    public void rotate(String gizmo) {
        edits.rotate(gizmo);
        edited();
    }

    /**
     * Deletes a gizmo (with its connections and key bindings; an absorber takes the balls it holds with it) or a
     * ball.
     */
    public void delete(String name) {
        edits.delete(name);
        gameRules = gameRules.without(name);
        edited();
    }

    /** Moves a gizmo to a new top-left cell, with the same checks as adding it there. */
    public void moveGizmo(String gizmo, int x, int y) {
        edits.moveGizmo(gizmo, x, y);
        edited();
    }

    /**
     * Moves gizmos and balls together by (dx, dy) L, as one edit: each must fit where it goes with the others
     * moved too (so a row moves along itself), or nothing moves. Gizmos move by whole cells; the balls an absorber
     * of the group holds go with it.
     */
    public void moveGroup(Collection<String> names, double dx, double dy) {
        edits.moveGroup(names, dx, dy);
        edited();
    }

    /**
     * Gives an absorber new corners ((x2, y2) exclusive, as {@link #addAbsorber}) with the same checks as adding it
     * there; it keeps its name, place in board order, colour, connections, keys, points and the balls it holds.
     */
    public void resizeAbsorber(String absorber, int x1, int y1, int x2, int y2) {
        edits.resizeAbsorber(absorber, x1, y1, x2, y2);
        edited();
    }

    /** Moves a ball's centre, with the same checks as adding it there; its velocity is kept unless captured. */
    public void moveBall(String ball, double x, double y) {
        edits.moveBall(ball, x, y);
        edited();
    }

    /**
     * Gives a ball a new velocity where it is, keeping its place in the board's order of balls (so a saved file
     * keeps its order). A ball held by an absorber has no velocity of its own: only zero is accepted for it.
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
        wiring.connect(source, target, order);
        edited();
    }

    public void disconnect(TriggerSource source, String target) {
        wiring.disconnect(source, target);
        edited();
    }

    /** The key's edge drives the gizmo as that edge does unless told ({@link KeyEdge#actionOf}), at once. */
    public void bindKey(int keyCode, KeyEdge edge, String gizmo) {
        bindKey(keyCode, edge, gizmo, Order.DEFAULT);
    }

    /** The key's edge drives the gizmo as {@code order} says: one of its kind's actions, after a delay. */
    public void bindKey(int keyCode, KeyEdge edge, String gizmo, Order order) {
        if (gameRules.nudge().flatMap(n -> n.wayOf(keyCode)).isPresent()) {
            throw new BoardEditException("key " + keyCode + " nudges the board: it drives nothing else");
        }
        wiring.bindKey(keyCode, edge, gizmo, order);
        edited();
    }

    public void unbindKey(int keyCode, KeyEdge edge, String gizmo) {
        wiring.unbindKey(keyCode, edge, gizmo);
        edited();
    }

    /** Gives a gizmo its own colour, or with empty back the colour of its kind. */
    public void setColour(String gizmo, Optional<Rgb> colour) {
        edits.setColour(gizmo, colour);
        edited();
    }

    /**
     * Gives a gizmo the value its kind holds beyond its place (an accelerator's factor, a spawner's velocity, a
     * spinner's speed, a portal's pair: {@link Setting}), checked by the setting itself.
     */
    public void set(String gizmo, Setting setting) {
        edits.set(gizmo, setting);
        edited();
    }

    /**
     * Opens a gate or puts a drop target down, as play left it (a board saved during play): its cell is nothing until
     * it is closed or raised.
     */
    public void setCellOpen(String cell) {
        edits.setCellOpen(cell);
        edited();
    }

    /**
     * Puts a spinner where play left it: its bar at {@code radians} (from +x toward +y), turning or stopped. A board
     * saved during play keeps its spinners this way; no free ball may be inside the bar there.
     */
    public void setSpinnerState(String spinner, double radians, boolean running) {
        edits.setSpinnerState(spinner, radians, running);
        edited();
    }

    public void setGravity(double g) {
        if (!Double.isFinite(g)) {
            throw new BoardEditException("gravity must be a finite number, got " + g);
        }
        gravity = g;
        edited();
    }

    public void setFriction(double newMu, double newMu2) {
        if (!Double.isFinite(newMu) || !Double.isFinite(newMu2) || newMu < 0 || newMu2 < 0) {
            throw new BoardEditException("friction must be finite and not negative, got mu " + newMu + ", mu2 " + newMu2);
        }
        mu = newMu;
        mu2 = newMu2;
        edited();
    }

    /** Removes everything, puts gravity and friction back to their defaults and the time to 0. */
    public void clear() {
        registry.clear();
        wiring.clear();
        gravity = DEFAULT_GRAVITY;
        mu = DEFAULT_MU;
        mu2 = DEFAULT_MU2;
        time = 0;
        play.clockMoved();
        play.forgetDelayed();
        ticks = 0;
        gameRules = GameRules.DEFAULT;
        game.reset();
        notifyObservers(BoardChange.REPLACE);
    }

    // ---------------------------------------------------------------- the game (docs/design.md, "The game")

    /** How many balls a game has (1 to {@link GameRules#MAX_BALLS}; three until said otherwise). */
    public void setBallsPerGame(int balls) {
        changeRules(() -> gameRules.withBallsPerGame(balls));
    }

    /** Makes an absorber a drain (a ball it captures is lost) or an ordinary absorber again. */
    public void setDrain(String absorber, boolean drain) {
        GizmoBase gizmo = registry.requireGizmo(absorber);
        if (drain && !gizmo.kind().canDrain()) {
            throw new BoardEditException("only an absorber can be a drain: " + absorber + " is "
                    + gizmo.kind().withArticle() + ", which captures no ball");
        }
        changeRules(() -> gameRules.withDrain(absorber, drain));
    }

    /** What a real hit on the gizmo scores (its kind's value unless set; within plus or minus a million). */
    public void setPoints(String gizmo, int points) {
        GizmoKind kind = registry.requireGizmo(gizmo).kind();
        changeRules(() -> gameRules.withPoints(gizmo, kind, points));
    }

    /** The score at which a game gives one extra ball, once; empty for none. */
    public void setExtraBallAt(OptionalLong score) {
        changeRules(() -> gameRules.withExtraBallAt(score));
    }

    /**
     * Lets the board be nudged with the nudge's keys, or with empty not at all. The keys must drive nothing on the
     * board: a key is a nudge key or a key of the board's bindings, never both.
     */
    public void setNudge(Optional<Nudge> nudge) {
        nudge.ifPresent(n -> {
            for (KeyBinding binding : wiring.keyBindings()) {
                if (n.wayOf(binding.keyCode()).isPresent()) {
                    throw new BoardEditException("key " + binding.keyCode() + " drives " + binding.gizmo()
                            + ": a nudge key drives nothing else");
                }
            }
        });
        changeRules(() -> gameRules.withNudge(nudge));
    }

    /** When nudging tilts the game (with a nudge: the board's {@link Tilt}, 4 nudges within 5 s unless set). */
    public void setTilt(Tilt tilt) {
        changeRules(() -> gameRules.withTilt(tilt));
    }

    /** For how many seconds after a launch a drained ball is given back, once (0: never, the default). */
    public void setBallSave(double seconds) {
        changeRules(() -> gameRules.withBallSave(seconds));
    }

    /**
     * A new game on this board is for that many players, 1 to {@link Game#MAX_PLAYERS}, taking turns ball by ball;
     * chosen before its first tick (a board made or reset has a game for as many as it had).
     */
    public void setPlayers(int players) {
        if (ticks > 0) {
            throw new IllegalStateException("the number of players is chosen before the first tick");
        }
        game.setPlayers(players);
    }

    private void changeRules(Supplier<GameRules> changed) {
        try {
            gameRules = changed.get();
        } catch (IllegalArgumentException refused) {
            throw new BoardEditException(refused.getMessage());
        }
        edited();
    }

    public GameRules gameRules() {
        return gameRules;
    }

    /** The game on this board: score, balls left, drains, game over (a sandbox scores too). */
    public GameProgress game() {
        return game;
    }

    /** Ticks run since the board was made or cleared: the clock of games, key scripts and replays. */
    public long ticks() {
        return ticks;
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
        List<Gizmo> all = new ArrayList<>();
        registry.gizmos().forEach(g -> all.add(asGizmo(g)));
        return Collections.unmodifiableList(all);
    }

    public Optional<Gizmo> gizmo(String name) {
        return Optional.ofNullable(registry.gizmo(name)).map(Board::asGizmo);
    }

    public Optional<Gizmo> gizmoAt(int cx, int cy) {
        return Optional.ofNullable(registry.index().at(cx, cy)).map(Board::asGizmo);
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
        return gravity;
    }

    public double mu() {
        return mu;
    }

    public double mu2() {
        return mu2;
    }

    /** Simulated seconds since construction or {@link #clear()}. */
    public double time() {
        return time;
    }

    private static Gizmo asGizmo(GizmoBase gizmo) {
        return (Gizmo) gizmo;
    }

    // ---------------------------------------------------------------- play

    /** One tick of the six-stage loop (docs/design.md, "The tick"); dt in seconds, finite and not negative. */
    public void tick(double dt) {
        if (!Double.isFinite(dt) || dt < 0) {
            throw new IllegalArgumentException("tick length must be finite and not negative, got " + dt);
        }
        play.performDue(time);
        play.ticking(true);
        lastTick = tickRun.run(dt);
        play.dropHitTargets(lastTick.events());
        play.ticking(false);
        play.removeSunk();
        play.holdPulls(dt);
        ticks++;
        game.afterTick(ticks, lastTick.events());
        guardsFired = guardsFired.plus(lastTick.guards());
        long start = System.nanoTime();
        notifyObservers(BoardChange.TICK);
        lastRedrawNanos = System.nanoTime() - start;
    }

    /** What the last tick did (stage times, collisions, balls awake, events); {@link TickReport#NONE} before any. */
    public TickReport lastTick() {
        return lastTick;
    }

    /** How often each last-resort guard of the loop has fired since this board was made. */
    public GuardCounts guardsFired() {
        return guardsFired;
    }

    /**
     * How far ahead, in seconds, each tick's report looks for every ball's next collision (0, the default: not at
     * all). The physics overlay turns it on; it costs a detection pass per ball and tick.
     */
    public void setNextCollisionLookAhead(double seconds) {
        if (!(seconds >= 0) || Double.isInfinite(seconds)) {
            throw new IllegalArgumentException("look-ahead must be finite and not negative, got " + seconds);
        }
        nextCollisionLookAhead = seconds;
    }

    /**
     * Performs the actions bound to (keyCode, DOWN): flippers swing up, others perform their action; and those
     * bound to (keyCode, CHANGE): every gizmo performs its action (a flipper toggles). The game records the key with
     * the tick ({@link GameProgress#keys()}), as it does every release.
     */
    public void keyDown(int keyCode) {
        keyAction(keyCode, KeyEdge.DOWN);
    }

    /** Performs the actions bound to (keyCode, UP): flippers swing back down, others perform their action. */
    public void keyUp(int keyCode) {
        keyAction(keyCode, KeyEdge.UP);
    }

    private void keyAction(int keyCode, KeyEdge edge) {
        game.keyPressed(ticks, edge == KeyEdge.DOWN ? KeyPress.Motion.DOWN : KeyPress.Motion.UP, keyCode);
        Optional<Nudge.Way> nudge = gameRules.nudge().flatMap(n -> n.wayOf(keyCode));
        if (nudge.isPresent()) {
            if (edge == KeyEdge.DOWN) {
                nudge(nudge.get());
            }
            return;
        }
        play.keyAction(wiring.keyBindings(), keyCode, edge, time, game.isTilted());
    }

    /**
     * Every free ball gets the nudge's speed that way, woken if asleep; held balls feel nothing. The nudge counts
     * toward the tilt: one that tilts lowers every flipper and lets go of every plunger's pull.
     */
    private void nudge(Nudge.Way way) {
        double speed = gameRules.nudge().orElseThrow().speed();
        Vect push = new Vect(way.dx() * speed, way.dy() * speed);
        sleepers.wakeWithin(-SIZE, -SIZE, 2 * SIZE, 2 * SIZE);
        for (Ball ball : registry.balls()) {
            if (!ball.isCaptured()) {
                ball.setVelocity(ball.velocity().plus(push));
            }
        }
        if (game.nudged(ticks)) {
            play.tilt();
        }
    }

    /** The gizmo performs its action: a flipper toggles, an absorber fires, a bumper only records the time. */
    public void trigger(String gizmo) {
        GizmoBase target = registry.gizmo(gizmo);
        if (target == null) {
            throw new IllegalArgumentException("cannot trigger " + gizmo + ": no gizmo named " + gizmo);
        }
        play.performAction(target, time);
    }

    public void addObserver(BoardObserver observer) {
        observers.add(observer);
    }

    public void removeObserver(BoardObserver observer) {
        observers.remove(observer);
    }

    /** After every successful edit: the board changed under the balls, which forget their contacts and wake. */
    private void edited() {
        sleepers.disturbAll();
        notifyObservers(BoardChange.EDIT);
    }

    void notifyObservers(BoardChange change) {
        observers.tell(this, change);
    }

    // ---------------------------------------------------------------- for tests and the benchmark
    // The game always plays CONTINUOUS with the index: only tests (directly or through their LoopModes fixture) and
    // the benchmark (through BenchSwitches, in its own source set) turn these, so they are not public.

    void setLoopMode(LoopMode mode) {
        if (mode == null) {
            throw new IllegalArgumentException("loop mode must not be null");
        }
        loopMode = mode;
    }

    LoopMode loopMode() {
        return loopMode;
    }

    /** True (default): collision detection asks the grid for reachable gizmos; false: it scans every gizmo. */
    void setSpatialIndexEnabled(boolean enabled) {
        spatialIndexEnabled = enabled;
    }

    boolean spatialIndexEnabled() {
        return spatialIndexEnabled;
    }

    double nextCollisionLookAhead() {
        return nextCollisionLookAhead;
    }

    /** How long the observers took to take in the last tick (what the loop's report says the redraw cost). */
    long lastRedrawNanos() {
        return lastRedrawNanos;
    }

    /** The loop moved the clock on by {@code dt}: so does every delayed action's. */
    void advanceTime(double dt) {
        time += dt;
        play.clockMoved();
    }

    /** Sum over free balls of |v|^2/2 + gravity * (SIZE - y), unit mass. */
    public double energy() {
        double total = 0;
        for (Ball ball : registry.balls()) {
            if (!ball.isCaptured()) {
                Vect v = ball.velocity();
                total += v.dot(v) / 2 + gravity * (SIZE - ball.position().y());
            }
        }
        return total;
    }

    // ---------------------------------------------------------------- for the invariants and the loop's tests

    Collection<GizmoBase> gizmoBases() {
        return registry.gizmos();
    }

    Collection<Ball> ballStates() {
        return registry.balls();
    }

    /** The loop's view of this board, for the loop's tests (through their fixture {@code LoopViews}). */
    LoopView loopView() {
        return loop;
    }
}
