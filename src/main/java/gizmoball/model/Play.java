package gizmoball.model;

import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.BallHolder;
import gizmoball.model.gizmo.BallSource;
import gizmoball.model.gizmo.BallTaking;
import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.MovingShape;
import gizmoball.model.gizmo.Plunger;
import gizmoball.model.gizmo.Surroundings;
import gizmoball.model.gizmo.SwitchedCell;
import gizmoball.model.loop.Arena;
import gizmoball.model.loop.Ball;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.Sleepers;

import java.util.HashSet;
import java.util.List;
import java.util.OptionalInt;
import java.util.Set;

import physics.Vect;

/**
 * The actions of play: keys, triggers and captures. What a gizmo does when driven is its own
 * ({@link GizmoBase#act}, {@link GizmoBase#keyDown}, {@link GizmoBase#keyUp}); this is what those actions do to the
 * board around it, the {@link Surroundings} the gizmo is handed: a flipper that starts to swing wakes the balls in its
 * box, an absorber fires only into a free spot. What waits for the tick's end is {@link EndOfTick}'s, what waits for
 * a delay {@link DelayedActions}'; the events go to the {@link EventLog}.
 */
final class Play implements Surroundings {
    private final Registry registry;
    private final PlacementRules rules;
    private final Sleepers sleepers;
    private final EventLog events;
    private final EndOfTick endOfTick;
    private final DelayedActions delayed;
    /** The absorbers that fired a ball since the board's clock last moved (in this tick). */
    private final Set<String> fired = new HashSet<>();

    Play(Registry registry, PlacementRules rules, Sleepers sleepers, EventLog events, EndOfTick endOfTick,
            DelayedActions delayed) {
        this.registry = registry;
        this.rules = rules;
        this.sleepers = sleepers;
        this.events = events;
        this.endOfTick = endOfTick;
        this.delayed = delayed;
    }

    /**
     * The key went down or up: the gizmos bound to that edge do what their binding orders (by default as keys drive
     * them: a flipper stays up while the key is held), and on DOWN those bound to CHANGE too (by default what a trigger
     * makes them do: a flipper toggles). A plunger that the press would fire at once is pulled instead, and fires when
     * that key goes up. While the game is tilted, flippers and plungers do not answer.
     */
    void keyAction(List<KeyBinding> bindings, int keyCode, KeyEdge edge, double now, boolean tilted) {
        if (edge == KeyEdge.UP) {
            releasePlungers(keyCode, now);
        }
        for (KeyBinding binding : bindings) {
            if (binding.keyCode() == keyCode
                    && (binding.edge() == edge || binding.edge() == KeyEdge.CHANGE && edge == KeyEdge.DOWN)) {
                GizmoBase gizmo = registry.gizmo(binding.gizmo());
                if (tilted && gizmo.workedByPlayer()) {
                    continue;
                }
                Action action = binding.order().action().orElse(binding.edge().actionOf(gizmo.kind()));
                if (edge == KeyEdge.DOWN && action == Action.FIRE && binding.order().delay() == 0
                        && gizmo instanceof BallHolder holder && holder.plunger().isPresent()) {
                    if (holder.pullingKey().isEmpty()) {
                        holder.markTriggered(now);
                        holder.startPull(keyCode);
                    }
                } else {
                    carryOut(gizmo, action, binding.order().delay(), now);
                }
            }
        }
    }

    /** The key went up: every plunger it pulls fires, at the speed its pull has reached. */
    private void releasePlungers(int keyCode, double now) {
        List<BallHolder> holders = registry.ballHolders();
        for (int i = 0; i < holders.size(); i++) {
            BallHolder holder = holders.get(i);
            if (holder.pullingKey().equals(OptionalInt.of(keyCode))) {
                double speed = holder.releaseSpeed();
                holder.letGoOfPull();
                holder.markTriggered(now);
                launch(holder, speed);
            }
        }
    }

    /** A tick of {@code dt} seconds ran: every plunger being pulled was held that much longer. */
    void holdPulls(double dt) {
        List<BallHolder> holders = registry.ballHolders();   // by index: this runs every tick
        for (int i = 0; i < holders.size(); i++) {
            if (holders.get(i).pullingKey().isPresent()) {
                holders.get(i).heldFor(dt);
            }
        }
    }

    /**
     * The game tilted: what the player works gives up (every flipper falls back to rest and every plunger lets go of
     * its pull without firing), and a tilted game's keys leave it dead ({@link GizmoBase#workedByPlayer}).
     */
    void tilt() {
        for (GizmoBase gizmo : registry.gizmos()) {
            gizmo.tilt(this);
        }
    }

    /** The board's clock moved on (a tick ended) or was set: every absorber may fire again. */
    void clockMoved() {
        fired.clear();
    }

    /** The gizmo named performs its kind's default action: a flipper toggles, an absorber fires, a bumper flashes. */
    void trigger(String name, double now) {
        GizmoBase gizmo = registry.gizmo(name);
        if (gizmo == null) {
            throw new IllegalArgumentException("cannot trigger " + name + ": no gizmo named " + name);
        }
        perform(gizmo, gizmo.kind().defaultAction(), now);
    }

    /**
     * The gizmo performs the action now or, after a delay, at the first tick boundary the delay has reached (before
     * the tick from there runs).
     */
    void carryOut(GizmoBase gizmo, Action action, double delay, double now) {
        if (delay == 0) {
            perform(gizmo, action, now);
        } else {
            delayed.add(now + delay, gizmo, action);
        }
    }

    void perform(GizmoBase gizmo, Action action, double now) {
        gizmo.markTriggered(now);
        gizmo.perform(action, this);
    }

    /** A flipper that starts to swing is heard (its swing event). */
    @Override
    public void swingStarted(String gizmo, boolean up) {
        events.record(new PlayEvent.Swing(gizmo, up));
    }

    /**
     * A moving shape that starts to move wakes every ball in its box (its whole sweep lies there) and what rests on
     * them.
     */
    @Override
    public void startedMoving(MovingShape shape) {
        wakeSweep(shape);
    }

    /** Wakes every ball in the moving shape's box, where all of its sweep lies, and what rests on them. */
    void wakeSweep(MovingShape moving) {
        double margin = 2 * Arena.BALL_RADIUS;
        sleepers.wakeWithin(moving.x() - margin, moving.y() - margin, moving.x() + moving.width() + margin,
                moving.y() + moving.height() + margin);
    }

    /**
     * Shoots the longest-held ball straight up from just above the top edge (at the standard speed, or a plunger's
     * full-pull speed: a trigger fires a plunger at once), if the spot there is free (inside
     * the board, no gizmo or free ball in the way); otherwise the ball stays held. An absorber fires at most once a
     * tick: a ball it fires into a ball wedged against the wall above, or a flipper a hair above its mouth, comes
     * straight back, and an absorber that its own capture triggers would fire it again and again, at no time or a
     * few microseconds apart, thousands of times a tick.
     */
    @Override
    public void fire(BallHolder holder) {
        launch(holder, holder.plunger().map(Plunger::fullSpeed).orElse(Board.ABSORBER_LAUNCH_SPEED));
    }

    /** Fires the longest-held ball straight up at {@code speed}, as {@link #fire} says. */
    private void launch(BallHolder holder, double speed) {
        List<String> held = holder.held();
        if (held.isEmpty()) {
            return;
        }
        String name = held.get(0);
        Vect launch = holder.launchPosition(Arena.BALL_RADIUS);
        if (fired.contains(holder.name())) {
            return;   // fired already in this tick: what came straight back stays held until the next
        }
        if (rules.freeForBall(launch)) {
            fired.add(holder.name());
            holder.letGo(name);
            registry.ball(name).release(launch, new Vect(0, -speed));
            events.record(new PlayEvent.Fired(holder.name()));
            double margin = 4 * Arena.BALL_RADIUS;
            sleepers.wakeWithin(launch.x() - margin, launch.y() - margin, launch.x() + margin, launch.y() + margin);
        }
    }

    /**
     * The gizmo takes the ball, at rest where it says: an absorber holds it at its bottom-right corner, behind any it
     * already holds; a sink stops it at its centre, out of play, until the tick's end takes it off the board
     * ({@link EndOfTick#removeSunk}).
     */
    void take(Ball ball, GizmoBase gizmo) {
        ball.capture(gizmo.take(ball.name(), Arena.BALL_RADIUS));
        if (gizmo.ballTaking() == BallTaking.REMOVES) {
            endOfTick.sunk(ball.name());
        }
    }

    /**
     * Adds a ball at the source's mouth with its velocity, if the mouth is free and the board holds fewer than
     * {@link BallSource#MAX_BALLS}; during a tick (a hit triggered it) at the tick's end, so that the loop meets no ball
     * it did not start with.
     */
    @Override
    public void spawn(BallSource source) {
        endOfTick.spawn(source.name(), () -> spawnNow(source));
    }

    private void spawnNow(BallSource source) {
        Vect mouth = source.mouth(Arena.BALL_RADIUS);
        if (registry.balls().size() >= BallSource.MAX_BALLS || !rules.freeForBall(mouth)) {
            return;
        }
        Ball ball = new Ball(registry.freshBallName(), mouth, Vect.ZERO);
        ball.setVelocity(source.velocity());
        registry.add(ball);
        events.record(new PlayEvent.Spawned(source.name(), ball.name()));
        double margin = 4 * Arena.BALL_RADIUS;
        sleepers.wakeWithin(mouth.x() - margin, mouth.y() - margin, mouth.x() + margin, mouth.y() + margin);
    }

    /**
     * Makes the gate or drop target nothing, or solid over a clear cell (else it waits as nothing, and becomes solid at
     * the first tick end with the cell clear); during a tick at the tick's end, so that the loop never loses a surface
     * it is resolving. Balls forget their contacts and wake, as after an edit: what they lay on may have gone.
     */
    @Override
    public void switchCell(SwitchedCell cell, boolean solid) {
        endOfTick.switchCell(cell, solid);
    }

    /** A gizmo that holds balls (an absorber), placed or moved, captures the free balls it now covers. */
    void captureFreeBallsIn(GizmoBase holder) {
        for (Ball ball : registry.balls()) {
            if (!ball.isCaptured() && Overlaps.ballInGizmo(holder, ball.position())) {
                take(ball, holder);
            }
        }
    }
}
