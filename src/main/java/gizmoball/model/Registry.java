package gizmoball.model;

import gizmoball.model.gizmo.BallHolder;
import gizmoball.model.gizmo.MovingShape;
import gizmoball.model.gizmo.SwitchedCell;
import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.loop.Arena;
import gizmoball.model.loop.Ball;
import gizmoball.model.loop.Sleepers;
import gizmoball.model.loop.SpatialIndex;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import physics.Vect;

/**
 * The gizmos and balls of a board by name, in board order, with the grid of cells the gizmos occupy, the moving
 * shapes among them, and the pairs of balls placed on each other. It keeps these consistent with each other and checks
 * nothing: {@link PlacementRules} decides what may be placed, {@link Board} what an edit does.
 */
final class Registry {
    private final Map<String, GizmoBase> gizmos = new LinkedHashMap<>();
    /** One map for the board's life: {@link Sleepers} holds a live view of its values. */
    private final Map<String, Ball> balls = new LinkedHashMap<>();
    private final Set<Set<String>> passingPairs = new HashSet<>();
    private SpatialIndex index = new SpatialIndex();
    /**
     * The moving shapes and the switched cells among the gizmos, found again after every change of the gizmos (null
     * until then): the loop and the end of every tick ask for them.
     */
    private List<MovingShape> movingShapes;
    private List<SwitchedCell> switchedCells;
    /** The gizmos that hold balls, found again likewise: every tick holds their pulls. */
    private List<BallHolder> ballHolders;
    /** The balls in board order, made again after a ball comes or goes (null till then): the loop walks it by index. */
    private List<Ball> ballList;

    /** Becomes a deep copy of source. */
    void copyFrom(Registry source) {
        clear();
        for (GizmoBase gizmo : source.gizmos.values()) {
            insert(gizmo.copy());
        }
        source.balls.values().forEach(ball -> balls.put(ball.name(), ball.copy()));
        ballList = null;
        passingPairs.addAll(source.passingPairs);
    }

    void clear() {
        gizmos.clear();
        balls.clear();
        ballList = null;
        passingPairs.clear();
        index = new SpatialIndex();
        kindsChanged();
    }

    Collection<GizmoBase> gizmos() {
        return gizmos.values();
    }

    Collection<Ball> balls() {
        return balls.values();
    }

    /** {@link #balls()} as a list, kept until a ball comes or goes. */
    List<Ball> ballList() {
        if (ballList == null) {
            ballList = List.copyOf(balls.values());
        }
        return ballList;
    }

    /** The gizmo of that name, or null. */
    GizmoBase gizmo(String name) {
        return gizmos.get(name);
    }

    /** The ball of that name, or null. */
    Ball ball(String name) {
        return balls.get(name);
    }

    boolean uses(String name) {
        return gizmos.containsKey(name) || balls.containsKey(name);
    }

    /** The gizmo of that name, or the refusal of an edit naming something else. */
    GizmoBase requireGizmo(String name) {
        GizmoBase gizmo = gizmos.get(name);
        if (gizmo == null) {
            throw new BoardEditException(balls.containsKey(name) ? name + " is a ball, not a gizmo"
                    : "no gizmo named " + name);
        }
        return gizmo;
    }

    SpatialIndex index() {
        return index;
    }

    void insert(GizmoBase gizmo) {
        gizmos.put(gizmo.name(), gizmo);
        index.put(gizmo);
        kindsChanged();
    }

    /** Removes the gizmo, and the balls it holds (an absorber's) with it. */
    void remove(GizmoBase gizmo) {
        index.remove(gizmo);
        gizmos.remove(gizmo.name());
        gizmo.held().forEach(balls::remove);
        ballList = null;
        kindsChanged();
    }

    /** Puts {@code replacement} (of the same name) where {@code gizmo} was: in its place in board order, in the grid. */
    void replace(GizmoBase gizmo, GizmoBase replacement) {
        index.remove(gizmo);
        gizmos.put(replacement.name(), replacement);
        index.put(replacement);
        kindsChanged();
    }

    /** Moves the gizmo to a new top-left cell, its cells in the grid with it. */
    void move(GizmoBase gizmo, int x, int y) {
        index.remove(gizmo);
        gizmo.moveTo(x, y);
        index.put(gizmo);
    }

    void add(Ball ball) {
        balls.put(ball.name(), ball);
        ballList = null;
    }

    void remove(Ball ball) {
        releaseFromAbsorber(ball);
        balls.remove(ball.name());
        ballList = null;
    }

    /** The ball leaves whichever absorber holds it. */
    void releaseFromAbsorber(Ball ball) {
        gizmos.values().forEach(g -> g.letGo(ball.name()));
    }

    private void kindsChanged() {
        movingShapes = null;
        switchedCells = null;
        ballHolders = null;
    }

    List<MovingShape> movingShapes() {
        if (movingShapes == null) {
            movingShapes = gizmosOf(MovingShape.class);
        }
        return movingShapes;
    }

    /** The gizmos that hold balls (absorbers), in board order. */
    List<BallHolder> ballHolders() {
        if (ballHolders == null) {
            ballHolders = gizmosOf(BallHolder.class);
        }
        return ballHolders;
    }

    /** The gates and drop targets, in board order. */
    List<SwitchedCell> switchedCells() {
        if (switchedCells == null) {
            switchedCells = gizmosOf(SwitchedCell.class);
        }
        return switchedCells;
    }

    private <T> List<T> gizmosOf(Class<T> type) {
        List<T> found = new ArrayList<>();
        for (GizmoBase gizmo : gizmos.values()) {
            if (type.isInstance(gizmo)) {
                found.add(type.cast(gizmo));
            }
        }
        return List.copyOf(found);
    }

    void passThrough(String a, String b) {
        passingPairs.add(Set.of(a, b));
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
        if (passingPairs.isEmpty()) {
            return;   // the usual board: none to look at, and no iterator made for none
        }
        passingPairs.removeIf(pair -> {
            List<Ball> two = pair.stream().map(balls::get).toList();
            return two.contains(null) || two.get(0).isCaptured() || two.get(1).isCaptured()
                    || !Overlaps.balls(two.get(0).position(), two.get(1).position());
        });
    }

    /** Sum over free balls of |v|^2/2 + gravity * (SIZE - y), unit mass. */
    double energy(double gravity) {
        double total = 0;
        for (Ball ball : balls.values()) {
            if (!ball.isCaptured()) {
                Vect v = ball.velocity();
                total += v.dot(v) / 2 + gravity * (Arena.SIZE - ball.position().y());
            }
        }
        return total;
    }

    /** "Ball1", "Ball2", ...: the first name no gizmo or ball has. */
    String freshBallName() {
        for (int n = 1; ; n++) {
            String name = "Ball" + n;
            if (gizmo(name) == null && ball(name) == null) {
                return name;
            }
        }
    }
}
