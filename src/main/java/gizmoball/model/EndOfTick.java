package gizmoball.model;

import gizmoball.model.gizmo.SwitchedCell;
import gizmoball.model.loop.Arena;
import gizmoball.model.loop.Ball;
import gizmoball.model.loop.Sleepers;
import gizmoball.model.loop.TickEvents;
import gizmoball.model.loop.Tolerances;
import gizmoball.model.loop.TriggerSource;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import physics.Vect;

/**
 * The changes of play that wait for the end of the tick in which they were asked for, so that the loop never meets a
 * ball it did not start with nor loses a surface it is resolving: spawns, gates and drop targets switched, the balls
 * sinks took. Between ticks they happen at once.
 */
final class EndOfTick {
    private final Registry registry;
    private final Sleepers sleepers;
    /** Whether a tick is running: what is asked for waits for its end. */
    private boolean ticking;
    /** The gates and drop targets told to be solid (true) or nothing during this tick, the last order of each. */
    private final Map<String, Boolean> cellOrders = new LinkedHashMap<>();
    /**
     * The spawns asked for during this tick, in order, and the sources that asked for them: one each. A source's later
     * spawns in the tick could never add a ball (its first left a ball in its mouth, or found the mouth taken or the
     * board full, and spawns only add balls), and on a spawner board each wall hit asks again: kept, each would look
     * among 200 balls for room at the tick's end.
     */
    private final List<Runnable> toSpawn = new ArrayList<>();
    private final List<String> spawning = new ArrayList<>();
    /** The balls sinks took in this tick, which leave the board when it is over. */
    private final List<String> sunk = new ArrayList<>();

    EndOfTick(Registry registry, Sleepers sleepers) {
        this.registry = registry;
        this.sleepers = sleepers;
    }

    /**
     * A spawn of the source named {@code source} ({@link Play#spawn}): at once between ticks, at the tick's end during
     * one (once, however often the source asks in the tick).
     */
    void spawn(String source, Runnable spawn) {
        if (ticking) {
            if (!spawning.contains(source)) {
                spawning.add(source);
                toSpawn.add(spawn);
            }
        } else {
            spawn.run();
        }
    }

    /** As {@link Play#switchCell}: at once between ticks, at the tick's end during one. */
    void switchCell(SwitchedCell cell, boolean solid) {
        if (ticking) {
            cellOrders.put(cell.name(), solid);
        } else {
            switchNow(cell, solid);
        }
    }

    private void switchNow(SwitchedCell cell, boolean solid) {
        boolean wasSolid = cell.isSolid();
        if (solid) {
            boolean blocked = blocked(cell);
            cell.set(!blocked, blocked);
        } else {
            cell.set(false, false);
        }
        if (cell.isSolid() != wasSolid) {
            sleepers.disturbNear(cell.x(), cell.y(), cell.x() + cell.width(), cell.y() + cell.height());
        }
    }

    /**
     * Whether a ball lies too far into the cell for it to turn solid. Its shape lies within its cells (as the spatial
     * index has it), so only a ball whose centre is within a radius of them can be in the way: a cell waiting on a
     * board of 200 balls is asked again at the end of every tick, and measuring every ball against its sides cost a
     * crowded board 3% of its CPU.
     */
    private boolean blocked(SwitchedCell cell) {
        double reach = Arena.BALL_RADIUS;
        List<Ball> balls = registry.ballList();
        for (int i = 0; i < balls.size(); i++) {
            Vect p = balls.get(i).position();
            if (p.x() > cell.x() - reach && p.x() < cell.x() + cell.width() + reach
                    && p.y() > cell.y() - reach && p.y() < cell.y() + cell.height() + reach
                    && cell.solidOver(p) < Arena.BALL_RADIUS - Tolerances.PLACEMENT) {
                return true;
            }
        }
        return false;
    }

    /**
     * The tick that is ending reported these events: every drop target a ball hit in it goes down at its end (after
     * any order it was given in the tick: the hit is what the ball saw last).
     */
    void dropHitTargets(TickEvents tickEvents) {
        for (int i = 0; i < tickEvents.size(); i++) {
            if (tickEvents.isHit(i) && tickEvents.struck(i) instanceof TriggerSource.OfGizmo struck
                    && registry.gizmo(struck.gizmo()) instanceof SwitchedCell cell && cell.fallsWhenHit()) {
                cellOrders.put(cell.name(), false);
            }
        }
    }

    /**
     * A tick starts or ends: spawns, gates and drop targets asked for while it runs wait for its end. A tick that
     * asked for none and left no cell waiting ends with nothing made.
     */
    void ticking(boolean inTick) {
        ticking = inTick;
        if (inTick) {
            return;
        }
        List<SwitchedCell> switched = registry.switchedCells();
        if (!cellOrders.isEmpty() || anyWaiting(switched)) {
            Map<String, Boolean> cells = new LinkedHashMap<>(cellOrders);
            cellOrders.clear();
            for (SwitchedCell cell : switched) {
                if (cell.isWaiting() && !cells.containsKey(cell.name())) {
                    cells.put(cell.name(), true);   // still waiting to be solid: the cell may be clear now
                }
            }
            cells.forEach((name, solid) -> {
                if (registry.gizmo(name) instanceof SwitchedCell cell) {
                    switchNow(cell, solid);
                }
            });
        }
        if (!toSpawn.isEmpty()) {
            List<Runnable> due = List.copyOf(toSpawn);
            toSpawn.clear();
            spawning.clear();
            due.forEach(Runnable::run);
        }
    }

    private static boolean anyWaiting(List<SwitchedCell> cells) {
        for (int i = 0; i < cells.size(); i++) {
            if (cells.get(i).isWaiting()) {
                return true;
            }
        }
        return false;
    }

    /** A sink took the ball, which leaves the board at the tick's end ({@link #removeSunk}). */
    void sunk(String ball) {
        sunk.add(ball);
    }

    /** The tick is over: the balls sinks took in it leave the board. */
    void removeSunk() {
        for (int i = 0; i < sunk.size(); i++) {
            registry.remove(registry.ball(sunk.get(i)));
        }
        sunk.clear();
    }
}
