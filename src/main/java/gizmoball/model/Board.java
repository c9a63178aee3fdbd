package gizmoball.model;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;

import physics.Vect;

/**
 * The game board: gizmos, balls, connections, key bindings and the physics constants, with the editing operations
 * (each succeeds completely or throws {@link BoardEditException} and changes nothing), queries, and play
 * ({@link #tick(double)}, keys, triggers). The physics loop itself lives in {@link TickRun}.
 *
 * <p>At over 800 lines this class is well over the project's 400: it is still the registry, the placement checks
 * and the actions of play in one. The placement rule itself has one home ({@link Overlaps}); splitting the rest
 * into a registry, placement rules and play actions behind this facade is the open part of the structure work.
 */
public final class Board {
    public static final int SIZE = 20;
    public static final double BALL_RADIUS = 0.25;
    public static final double MAX_SPEED = 200;
    public static final double DEFAULT_GRAVITY = 25;
    public static final double DEFAULT_MU = 0.025;
    public static final double DEFAULT_MU2 = 0.025;
    public static final double DEFAULT_TICK = 1.0 / 60;
    public static final double ABSORBER_LAUNCH_SPEED = 50;

    private final Map<String, GizmoBase> gizmos = new LinkedHashMap<>();
    private final Map<String, Ball> balls = new LinkedHashMap<>();
    private final List<Connection> connections = new ArrayList<>();
    private final Set<Set<String>> passingPairs = new HashSet<>();
    private final List<KeyBinding> keyBindings = new ArrayList<>();
    private SpatialIndex index = new SpatialIndex();
    private double gravity = DEFAULT_GRAVITY;
    private double mu = DEFAULT_MU;
    private double mu2 = DEFAULT_MU2;
    private double time;
    private boolean spatialIndexEnabled = true;
    private LoopMode loopMode = LoopMode.CONTINUOUS;
    private final List<BoardObserver> observers = new CopyOnWriteArrayList<>();
    private final Sleepers sleepers = new Sleepers(balls.values());
    /** Reused by every tick: the broad phase for ball pairs. */
    private final BallGrid ballGrid = new BallGrid();
    /** The flippers among the gizmos, found again after every change of the gizmos (null until then). */
    private List<Flipper> flippers;
    private final List<PlayEvent> pendingEvents = new ArrayList<>();
    private TickReport lastTick = TickReport.NONE;
    private GuardCounts guardsFired = GuardCounts.NONE;
    private long lastRedrawNanos;
    private double nextCollisionLookAhead;

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
        gizmos.clear();
        balls.clear();
        index = new SpatialIndex();
        for (GizmoBase gizmo : source.gizmos.values()) {
            GizmoBase copy = gizmo.copy();
            gizmos.put(copy.name(), copy);
            index.put(copy);
        }
        source.balls.values().forEach(ball -> balls.put(ball.name(), ball.copy()));
        connections.clear();
        connections.addAll(source.connections);
        passingPairs.clear();
        passingPairs.addAll(source.passingPairs);
        keyBindings.clear();
        keyBindings.addAll(source.keyBindings);
        gravity = source.gravity;
        mu = source.mu;
        mu2 = source.mu2;
        time = source.time;
        loopMode = source.loopMode;
        spatialIndexEnabled = source.spatialIndexEnabled;
    }

    // ---------------------------------------------------------------- editing

    public void addGizmo(GizmoKind kind, String name, int x, int y) {
        if (kind == null || kind == GizmoKind.ABSORBER) {
            throw new BoardEditException("cannot add " + name + ": addGizmo takes a bumper or flipper kind, not "
                    + kind + " (absorbers are added with their corners)");
        }
        requireFreshName(name);
        GizmoBase candidate = switch (kind) {
            case SQUARE, CIRCLE, TRIANGLE -> new Bumper(kind, name, x, y);
            default -> new Flipper(kind, name, x, y);
        };
        refuseIfPresent(problemFor(candidate, null));
        insert(candidate);
        edited();
    }

    /** Adds an absorber covering the cells from (x1, y1) to the exclusive corner (x2, y2). */
    public void addAbsorber(String name, int x1, int y1, int x2, int y2) {
        requireFreshName(name);
        if (x2 <= x1 || y2 <= y1) {
            throw new BoardEditException("absorber " + name + " from (" + x1 + "," + y1 + ") to (" + x2 + "," + y2
                    + ") must be at least one cell wide and high ((x2, y2) is the exclusive bottom-right corner)");
        }
        Absorber candidate = new Absorber(name, x1, y1, x2 - x1, y2 - y1);
        refuseIfPresent(problemFor(candidate, null));
        insert(candidate);
        captureFreeBallsIn(candidate);
        edited();
    }

    /**
     * Adds a ball (centre, velocity). The centre must be inside the board with the radius, the ball must not
     * overlap another free ball or a gizmo other than an absorber; one placed overlapping an absorber is captured.
     */
    public void addBall(String name, double x, double y, double vx, double vy) {
        placeBall(name, x, y, vx, vy, false);
    }

    /**
     * As {@link #addBall}, except that other free balls in the way do not refuse it (board files of other
     * implementations place balls on each other; the loop lets such a pair pass through until it separates).
     * Every other check stays. Returns the free balls it overlaps, in board order (none if it is captured).
     */
    public List<String> addBallOverlappingBalls(String name, double x, double y, double vx, double vy) {
        Ball ball = placeBall(name, x, y, vx, vy, true);
        List<String> overlapped = ball.isCaptured() ? List.of() : balls.values().stream()
                .filter(other -> other != ball && !other.isCaptured()
                        && Overlaps.balls(other.position(), ball.position()))
                .map(Ball::name)
                .toList();
        overlapped.forEach(other -> passingPairs.add(Set.of(name, other)));
        return overlapped;
    }

    /**
     * The pairs of balls placed on each other that have not come apart since: detection lets them pass through
     * each other. A pair leaves the set at the end of the first tick it no longer overlaps.
     */
    boolean passingThrough(Ball a, Ball b) {
        return !passingPairs.isEmpty() && passingPairs.contains(Set.of(a.name(), b.name()));
    }

    /** Forgets the passing pairs that have come apart (or lost a ball to an absorber or a delete). */
    void forgetSeparatedPairs() {
        passingPairs.removeIf(pair -> {
            List<Ball> two = pair.stream().map(balls::get).toList();
            return two.contains(null) || two.get(0).isCaptured() || two.get(1).isCaptured()
                    || !Overlaps.balls(two.get(0).position(), two.get(1).position());
        });
    }

    private Ball placeBall(String name, double x, double y, double vx, double vy, boolean ballsMayOverlap) {
        requireFreshName(name);
        if (!Double.isFinite(vx) || !Double.isFinite(vy)) {
            throw new BoardEditException("ball " + name + ": velocity (" + vx + "," + vy + ") must be finite");
        }
        Vect position = new Vect(requireFinite(x, name), requireFinite(y, name));
        Absorber captor = ballPlacementCaptor(name, position, null, ballsMayOverlap);
        Ball ball = new Ball(name, position, Vect.ZERO);
        ball.setVelocity(new Vect(vx, vy));
        balls.put(name, ball);
        if (captor != null) {
            capture(ball, captor);
        }
        edited();
        return ball;
    }

    /**
     * Puts a flipper where play left it: {@code degrees} from rest (0 to 90), swinging toward its active stop when
     * {@code active}, else toward rest. A board saved during play keeps its flippers this way; no free ball may be
     * inside the flipper there.
     */
    public void setFlipperState(String flipper, double degrees, boolean active) {
        if (!(requireGizmo(flipper) instanceof Flipper target)) {
            throw new BoardEditException(flipper + " is not a flipper");
        }
        if (!(degrees >= 0 && degrees <= Flipper.MAX_ANGLE)) {
            throw new BoardEditException("flipper " + flipper + ": angle " + degrees + " must be from 0 to "
                    + Flipper.MAX_ANGLE + " degrees");
        }
        Flipper candidate = target.copy();
        candidate.setState(degrees, active);
        refuseIfPresent(ballOverlap(candidate).map(ball -> "flipper " + flipper + " at " + degrees
                + " degrees would overlap ball " + ball));
        target.setState(degrees, active);
        edited();
    }

    /** Turns a gizmo 90 degrees clockwise within its footprint; circles and absorbers stay as they are. */
    public void rotate(String gizmo) {
        GizmoBase target = requireGizmo(gizmo);
        if (target.rotates()) {
            GizmoBase candidate = target.copy();
            candidate.rotateClockwise();
            refuseIfPresent(ballOverlap(candidate).map(ball -> "rotating " + gizmo + " would make it overlap ball "
                    + ball));
            target.rotateClockwise();
        }
        edited();
    }

    /**
     * Deletes a gizmo (with its connections and key bindings; an absorber takes the balls it holds with it) or a
     * ball.
     */
    public void delete(String name) {
        GizmoBase gizmo = gizmos.get(name);
        if (gizmo != null) {
            index.remove(gizmo);
            gizmos.remove(name);
            connections.removeIf(c -> c.source().equals(TriggerSource.gizmo(name)) || c.target().equals(name));
            keyBindings.removeIf(k -> k.gizmo().equals(name));
            if (gizmo instanceof Absorber absorber) {
                absorber.held().forEach(balls::remove);
            }
        } else if (balls.containsKey(name)) {
            releaseFromAbsorber(name);
            balls.remove(name);
        } else {
            throw new BoardEditException("cannot delete " + name + ": no gizmo or ball named " + name);
        }
        edited();
    }

    /** Moves a gizmo to a new top-left cell, with the same checks as adding it there. */
    public void moveGizmo(String gizmo, int x, int y) {
        GizmoBase target = requireGizmo(gizmo);
        GizmoBase candidate = target.copy();
        candidate.moveTo(x, y);
        refuseIfPresent(problemFor(candidate, gizmo));
        index.remove(target);
        target.moveTo(x, y);
        index.put(target);
        if (target instanceof Absorber absorber) {
            absorber.held().forEach(held -> balls.get(held).capture(absorber.holdingPosition()));
            captureFreeBallsIn(absorber);
        }
        edited();
    }

    /** Moves a ball's centre, with the same checks as adding it there; its velocity is kept unless captured. */
    public void moveBall(String ball, double x, double y) {
        Ball target = balls.get(ball);
        if (target == null) {
            throw new BoardEditException("cannot move " + ball + ": no ball named " + ball);
        }
        Vect position = new Vect(requireFinite(x, ball), requireFinite(y, ball));
        Absorber captor = ballPlacementCaptor(ball, position, ball, false);
        if (target.isCaptured()) {
            releaseFromAbsorber(ball);
            target.release(position, Vect.ZERO);
        } else {
            target.moveTo(position);
        }
        if (captor != null) {
            capture(target, captor);
        }
        edited();
    }

    /**
     * Gives a ball a new velocity where it is, keeping its place in the board's order of balls (so a saved file
     * keeps its order). A ball held by an absorber has no velocity of its own: only zero is accepted for it.
     */
    public void setBallVelocity(String ball, double vx, double vy) {
        Ball target = balls.get(ball);
        if (target == null) {
            throw new BoardEditException("cannot set the velocity of " + ball + ": no ball named " + ball);
        }
        if (!Double.isFinite(vx) || !Double.isFinite(vy)) {
            throw new BoardEditException("ball " + ball + ": velocity (" + vx + ", " + vy + ") is not finite");
        }
        Vect velocity = new Vect(vx, vy);
        if (target.isCaptured()) {
            if (!velocity.equals(Vect.ZERO)) {
                throw new BoardEditException(ball + " is held by an absorber: it cannot be given a velocity");
            }
            return;
        }
        target.setVelocity(velocity);
        edited();
    }

    /** Whenever source (a gizmo or the outer walls) is hit, target performs its action. Self-connections allowed. */
    public void connect(TriggerSource source, String target) {
        requireSource(source);
        requireGizmo(target);
        Connection connection = new Connection(source, target);
        if (connections.contains(connection)) {
            throw new BoardEditException("connection " + source + " -> " + target + " already exists");
        }
        connections.add(connection);
        edited();
    }

    public void disconnect(TriggerSource source, String target) {
        if (!connections.remove(new Connection(source, target))) {
            throw new BoardEditException("there is no connection " + source + " -> " + target);
        }
        edited();
    }

    public void bindKey(int keyCode, KeyEdge edge, String gizmo) {
        if (keyCode < 0) {
            throw new BoardEditException("key code must be 0 or more, got " + keyCode);
        }
        if (edge == null) {
            throw new BoardEditException("key binding for " + gizmo + " needs an edge, DOWN or UP");
        }
        requireGizmo(gizmo);
        KeyBinding binding = new KeyBinding(keyCode, edge, gizmo);
        if (keyBindings.contains(binding)) {
            throw new BoardEditException("key " + keyCode + " " + edgeName(edge) + " is already bound to " + gizmo);
        }
        keyBindings.add(binding);
        edited();
    }

    public void unbindKey(int keyCode, KeyEdge edge, String gizmo) {
        if (!keyBindings.remove(new KeyBinding(keyCode, edge, gizmo))) {
            throw new BoardEditException("key " + keyCode + " " + edgeName(edge) + " is not bound to " + gizmo);
        }
        edited();
    }

    /** Gives a gizmo its own colour, or with empty back the colour of its kind. */
    public void setColour(String gizmo, Optional<Rgb> colour) {
        if (colour == null) {
            throw new BoardEditException("colour of " + gizmo + " must be a colour or empty, not null");
        }
        requireGizmo(gizmo).setColour(colour);
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
        gizmos.clear();
        balls.clear();
        connections.clear();
        keyBindings.clear();
        passingPairs.clear();
        index = new SpatialIndex();
        gravity = DEFAULT_GRAVITY;
        mu = DEFAULT_MU;
        mu2 = DEFAULT_MU2;
        time = 0;
        notifyObservers(BoardChange.REPLACE);
    }

    /**
     * Why a gizmo of that kind and footprint cannot have its top-left cell at (x, y), ignoring the gizmo named
     * {@code ignoring} (may be null), or empty if it can. Checks the board edges, other gizmos and balls.
     */
    public Optional<String> placementProblem(GizmoKind kind, int x, int y, int width, int height, String ignoring) {
        if (kind == null) {
            return Optional.of("no gizmo kind given");
        }
        if (kind == GizmoKind.ABSORBER) {
            if (width < 1 || height < 1) {
                return Optional.of("an absorber must be at least one cell wide and high, not " + width + "x" + height);
            }
            return problemFor(new Absorber("", x, y, width, height), ignoring);
        }
        if (width != kind.width() || height != kind.height()) {
            return Optional.of("a " + kindName(kind) + " is " + kind.width() + "x" + kind.height() + " cells, not "
                    + width + "x" + height);
        }
        GizmoBase candidate = kind == GizmoKind.LEFT_FLIPPER || kind == GizmoKind.RIGHT_FLIPPER
                ? new Flipper(kind, "", x, y) : new Bumper(kind, "", x, y);
        GizmoBase moving = ignoring == null ? null : gizmos.get(ignoring);
        if (moving != null && moving.kind() == kind) {
            for (int i = 0; i < moving.rotation(); i++) {
                candidate.rotateClockwise();
            }
        }
        return problemFor(candidate, ignoring);
    }

    /** Footprint inside the board, no other gizmo's cells (but the ignored one's), no free ball inside the shape. */
    private Optional<String> problemFor(GizmoBase candidate, String ignoring) {
        String what = (candidate.name().isEmpty() ? "a " + kindName(candidate.kind()) : "gizmo " + candidate.name())
                + " at (" + candidate.x() + "," + candidate.y() + ")";
        for (int cx = candidate.x(); cx < candidate.x() + candidate.width(); cx++) {
            for (int cy = candidate.y(); cy < candidate.y() + candidate.height(); cy++) {
                if (!SpatialIndex.inside(cx, cy)) {
                    return Optional.of(what + " would leave the board: cell (" + cx + "," + cy + ") is outside it");
                }
            }
        }
        for (int cx = candidate.x(); cx < candidate.x() + candidate.width(); cx++) {
            for (int cy = candidate.y(); cy < candidate.y() + candidate.height(); cy++) {
                GizmoBase occupant = index.at(cx, cy);
                if (occupant != null && !occupant.name().equals(ignoring)) {
                    return Optional.of(what + " would overlap gizmo " + occupant.name());
                }
            }
        }
        if (candidate instanceof Absorber) {
            return Optional.empty();   // free balls under a new absorber are captured, not in the way
        }
        return ballOverlap(candidate).map(ball -> what + " would overlap ball " + ball);
    }

    /** The first free ball that would be inside the candidate's body. */
    private Optional<String> ballOverlap(GizmoBase candidate) {
        return balls.values().stream()
                .filter(ball -> !ball.isCaptured())
                .filter(ball -> Overlaps.ballInGizmo(candidate, ball.position()))
                .map(Ball::name)
                .findFirst();
    }

    /**
     * Checks a ball position (for the ball named {@code name}, ignoring ball {@code ignoring}) and returns the
     * absorber that would capture it there, or null.
     */
    private Absorber ballPlacementCaptor(String name, Vect position, String ignoring, boolean ballsMayOverlap) {
        String what = "ball " + name + " at (" + position.x() + "," + position.y() + ")";
        if (!insideBoard(position)) {
            throw new BoardEditException(what + " is outside the board (its centre must be at least " + BALL_RADIUS
                    + " L inside each wall)");
        }
        List<GizmoBase> near = index.within(position.x() - BALL_RADIUS, position.y() - BALL_RADIUS,
                position.x() + BALL_RADIUS, position.y() + BALL_RADIUS);
        Absorber captor = null;
        for (GizmoBase gizmo : near) {
            if (Overlaps.ballInGizmo(gizmo, position)) {
                if (gizmo instanceof Absorber absorber) {
                    captor = absorber;
                } else {
                    throw new BoardEditException(what + " would overlap gizmo " + gizmo.name());
                }
            }
        }
        if (captor == null && !ballsMayOverlap) {
            for (Ball other : balls.values()) {
                if (!other.isCaptured() && !other.name().equals(ignoring)
                        && Overlaps.balls(other.position(), position)) {
                    throw new BoardEditException(what + " would overlap ball " + other.name());
                }
            }
        }
        return captor;
    }


    static boolean insideBoard(Vect position) {
        return position.x() >= BALL_RADIUS && position.x() <= SIZE - BALL_RADIUS
                && position.y() >= BALL_RADIUS && position.y() <= SIZE - BALL_RADIUS;
    }

    private static double requireFinite(double coordinate, String ball) {
        if (!Double.isFinite(coordinate)) {
            throw new BoardEditException("ball " + ball + ": position " + coordinate + " is not a finite number");
        }
        return coordinate;
    }

    private void requireFreshName(String name) {
        if (name == null || name.isEmpty() || name.chars().anyMatch(Character::isWhitespace)) {
            throw new BoardEditException("name '" + name + "' must be non-empty and contain no whitespace");
        }
        if (name.equals(TriggerSource.OuterWalls.NAME)) {
            throw new BoardEditException("name " + name + " is reserved for the outer walls");
        }
        if (gizmos.containsKey(name) || balls.containsKey(name)) {
            throw new BoardEditException("name " + name + " is already used");
        }
    }

    private GizmoBase requireGizmo(String name) {
        GizmoBase gizmo = gizmos.get(name);
        if (gizmo == null) {
            throw new BoardEditException(balls.containsKey(name) ? name + " is a ball, not a gizmo"
                    : "no gizmo named " + name);
        }
        return gizmo;
    }

    private void requireSource(TriggerSource source) {
        if (source == null) {
            throw new BoardEditException("a connection needs a source: a gizmo or the outer walls");
        }
        if (source instanceof TriggerSource.OfGizmo gizmo) {
            requireGizmo(gizmo.gizmo());
        }
    }

    private static void refuseIfPresent(Optional<String> problem) {
        if (problem.isPresent()) {
            throw new BoardEditException(problem.get());
        }
    }

    private void insert(GizmoBase gizmo) {
        gizmos.put(gizmo.name(), gizmo);
        index.put(gizmo);
    }

    private void captureFreeBallsIn(Absorber absorber) {
        for (Ball ball : balls.values()) {
            if (!ball.isCaptured() && Overlaps.ballInGizmo(absorber, ball.position())) {
                capture(ball, absorber);
            }
        }
    }

    private void releaseFromAbsorber(String ball) {
        gizmos.values().stream()
                .filter(g -> g instanceof Absorber)
                .forEach(g -> ((Absorber) g).held().remove(ball));
    }

    private static String kindName(GizmoKind kind) {
        return kind.name().toLowerCase(Locale.ROOT).replace('_', ' ');
    }

    private static String edgeName(KeyEdge edge) {
        return edge == null ? "?" : edge.name().toLowerCase(Locale.ROOT);
    }

    // ---------------------------------------------------------------- queries

    public List<Gizmo> gizmos() {
        List<Gizmo> all = new ArrayList<>();
        gizmos.values().forEach(g -> all.add(asGizmo(g)));
        return Collections.unmodifiableList(all);
    }

    public Optional<Gizmo> gizmo(String name) {
        return Optional.ofNullable(gizmos.get(name)).map(Board::asGizmo);
    }

    public Optional<Gizmo> gizmoAt(int cx, int cy) {
        return Optional.ofNullable(index.at(cx, cy)).map(Board::asGizmo);
    }

    public List<Ball> balls() {
        return Collections.unmodifiableList(new ArrayList<>(balls.values()));
    }

    public Optional<Ball> ball(String name) {
        return Optional.ofNullable(balls.get(name));
    }

    public List<Connection> connections() {
        return List.copyOf(connections);
    }

    public List<KeyBinding> keyBindings() {
        return List.copyOf(keyBindings);
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

    /** One tick of the six-stage loop of SPEC.md (see {@link TickRun}); dt in seconds, finite and not negative. */
    public void tick(double dt) {
        if (!Double.isFinite(dt) || dt < 0) {
            throw new IllegalArgumentException("tick length must be finite and not negative, got " + dt);
        }
        lastTick = new TickRun(this, dt).run();
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

    double nextCollisionLookAhead() {
        return nextCollisionLookAhead;
    }

    long lastRedrawNanos() {
        return lastRedrawNanos;
    }

    void recordEvent(PlayEvent event) {
        pendingEvents.add(event);
    }

    /** The events since the last tick's report, for this tick's. */
    List<PlayEvent> drainEvents() {
        List<PlayEvent> events = List.copyOf(pendingEvents);
        pendingEvents.clear();
        return events;
    }

    Sleepers sleepers() {
        return sleepers;
    }

    BallGrid ballGrid() {
        return ballGrid;
    }

    List<Flipper> flippers() {
        if (flippers == null) {
            List<Flipper> found = new ArrayList<>();
            for (GizmoBase gizmo : gizmos.values()) {
                if (gizmo instanceof Flipper flipper) {
                    found.add(flipper);
                }
            }
            flippers = List.copyOf(found);
        }
        return flippers;
    }

    /**
     * Performs the actions bound to (keyCode, DOWN): flippers swing up, others perform their action; and those
     * bound to (keyCode, CHANGE): every gizmo performs its action (a flipper toggles).
     */
    public void keyDown(int keyCode) {
        keyAction(keyCode, KeyEdge.DOWN);
    }

    /** Performs the actions bound to (keyCode, UP): flippers swing back down, others perform their action. */
    public void keyUp(int keyCode) {
        keyAction(keyCode, KeyEdge.UP);
    }

    private void keyAction(int keyCode, KeyEdge edge) {
        for (KeyBinding binding : List.copyOf(keyBindings)) {
            if (binding.keyCode() == keyCode && binding.edge() == KeyEdge.CHANGE && edge == KeyEdge.DOWN) {
                performAction(gizmos.get(binding.gizmo()), time);
            } else if (binding.keyCode() == keyCode && binding.edge() == edge) {
                GizmoBase gizmo = gizmos.get(binding.gizmo());
                if (gizmo instanceof Flipper flipper) {
                    flipper.markTriggered(time);
                    boolean wasMoving = flipper.isMoving();
                    if (edge == KeyEdge.DOWN) {
                        flipper.activate();
                    } else {
                        flipper.deactivate();
                    }
                    swung(flipper, wasMoving);
                } else {
                    performAction(gizmo, time);
                }
            }
        }
    }

    /** The gizmo performs its action: a flipper toggles, an absorber fires, a bumper only records the time. */
    public void trigger(String gizmo) {
        GizmoBase target = gizmos.get(gizmo);
        if (target == null) {
            throw new IllegalArgumentException("cannot trigger " + gizmo + ": no gizmo named " + gizmo);
        }
        performAction(target, time);
    }

    void performAction(GizmoBase gizmo, double now) {
        gizmo.markTriggered(now);
        if (gizmo instanceof Flipper flipper) {
            boolean wasMoving = flipper.isMoving();
            flipper.toggle();
            swung(flipper, wasMoving);
        } else if (gizmo instanceof Absorber absorber) {
            fire(absorber);
        }
    }

    /**
     * A flipper that starts to swing wakes every ball in its box (its whole sweep lies there) and what rests on them.
     */
    private void swung(Flipper flipper, boolean wasMoving) {
        if (flipper.isMoving() && !wasMoving) {
            recordEvent(new PlayEvent.Swing(flipper.name(), flipper.isActive()));
            wakeSweep(flipper);
        }
    }

    /** Wakes every ball in the flipper's box, where all of its sweep lies, and what rests on them. */
    void wakeSweep(Flipper flipper) {
        double margin = 2 * BALL_RADIUS;
        sleepers.wakeWithin(flipper.x() - margin, flipper.y() - margin, flipper.x() + flipper.width() + margin,
                flipper.y() + flipper.height() + margin);
    }

    /**
     * Shoots the longest-held ball straight up from just above the top edge, if the spot there is free (inside
     * the board, no gizmo or free ball in the way); otherwise the ball stays held.
     */
    private void fire(Absorber absorber) {
        String name = absorber.held().peekFirst();
        if (name == null) {
            return;
        }
        Vect launch = absorber.launchPosition();
        boolean blocked = !insideBoard(launch)
                || gizmos.values().stream().anyMatch(g -> Overlaps.ballInGizmo(g, launch))
                || balls.values().stream().anyMatch(b -> !b.isCaptured()
                && Overlaps.balls(b.position(), launch));
        if (!blocked) {
            absorber.held().removeFirst();
            balls.get(name).release(launch, new Vect(0, -ABSORBER_LAUNCH_SPEED));
            recordEvent(new PlayEvent.Fired(absorber.name()));
            double margin = 4 * BALL_RADIUS;
            sleepers.wakeWithin(launch.x() - margin, launch.y() - margin, launch.x() + margin, launch.y() + margin);
        }
    }

    /** Holds the ball at the absorber's bottom-right corner, at rest, behind any it already holds. */
    void capture(Ball ball, Absorber absorber) {
        ball.capture(absorber.holdingPosition());
        absorber.held().addLast(ball.name());
    }

    public void addObserver(BoardObserver observer) {
        observers.add(observer);
    }

    public void removeObserver(BoardObserver observer) {
        observers.remove(observer);
    }

    /** After every successful edit: the board changed under the balls, which forget their contacts and wake. */
    private void edited() {
        flippers = null;
        sleepers.disturbAll();
        notifyObservers(BoardChange.EDIT);
    }

    void notifyObservers(BoardChange change) {
        if (change != BoardChange.TICK) {
            flippers = null;   // replaced or cleared: other gizmos
        }
        for (BoardObserver observer : observers) {
            observer.boardChanged(this, change);
        }
    }

    // ---------------------------------------------------------------- for tests and the benchmark

    public void setLoopMode(LoopMode mode) {
        if (mode == null) {
            throw new IllegalArgumentException("loop mode must not be null");
        }
        loopMode = mode;
    }

    public LoopMode loopMode() {
        return loopMode;
    }

    /** True (default): collision detection asks the grid for reachable gizmos; false: it scans every gizmo. */
    public void setSpatialIndexEnabled(boolean enabled) {
        spatialIndexEnabled = enabled;
    }

    boolean spatialIndexEnabled() {
        return spatialIndexEnabled;
    }

    /** Sum over free balls of |v|^2/2 + gravity * (SIZE - y), unit mass. */
    public double energy() {
        double total = 0;
        for (Ball ball : balls.values()) {
            if (!ball.isCaptured()) {
                Vect v = ball.velocity();
                total += v.dot(v) / 2 + gravity * (SIZE - ball.position().y());
            }
        }
        return total;
    }

    // ---------------------------------------------------------------- for the loop and the invariants

    Collection<GizmoBase> gizmoBases() {
        return gizmos.values();
    }

    Collection<Ball> ballStates() {
        return balls.values();
    }

    GizmoBase gizmoBase(String name) {
        return gizmos.get(name);
    }

    Ball ballState(String name) {
        return balls.get(name);
    }

    SpatialIndex index() {
        return index;
    }

    void advanceTime(double dt) {
        time += dt;
    }
}
