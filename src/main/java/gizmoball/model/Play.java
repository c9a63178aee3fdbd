package gizmoball.model;

import gizmoball.model.gizmo.Absorber;
import gizmoball.model.gizmo.Flipper;
import gizmoball.model.gizmo.MovingShape;
import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.Surroundings;
import gizmoball.model.loop.Ball;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.Sleepers;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import physics.Vect;

/**
 * The actions of play: keys, triggers and captures. What a gizmo does when driven is its own
 * ({@link GizmoBase#act}, {@link GizmoBase#keyDown}, {@link GizmoBase#keyUp}); this is what those actions do to the
 * board around it, the {@link Surroundings} the gizmo is handed: a flipper that starts to swing wakes the balls in its
 * box, an absorber fires only into a free spot. It also keeps the events of play (for sound and flashes) until the
 * tick reports them.
 */
final class Play implements Surroundings {
    private final Registry registry;
    private final PlacementRules rules;
    private final Sleepers sleepers;
    private final List<PlayEvent> pendingEvents = new ArrayList<>();
    /** The absorbers that fired a ball since the board's clock last moved (in this tick). */
    private final Set<String> fired = new HashSet<>();

    Play(Registry registry, PlacementRules rules, Sleepers sleepers) {
        this.registry = registry;
        this.rules = rules;
        this.sleepers = sleepers;
    }

    /**
     * The key went down or up: the gizmos bound to that edge are driven as keys drive them (a flipper stays up
     * while the key is held), and on DOWN those bound to CHANGE perform their action (a flipper toggles).
     */
    void keyAction(List<KeyBinding> bindings, int keyCode, KeyEdge edge, double now) {
        for (KeyBinding binding : bindings) {
            if (binding.keyCode() != keyCode) {
                continue;
            }
            GizmoBase gizmo = registry.gizmo(binding.gizmo());
            if (binding.edge() == KeyEdge.CHANGE && edge == KeyEdge.DOWN) {
                performAction(gizmo, now);
            } else if (binding.edge() == edge) {
                gizmo.markTriggered(now);
                if (edge == KeyEdge.DOWN) {
                    gizmo.keyDown(this);
                } else {
                    gizmo.keyUp(this);
                }
            }
        }
    }

    /** The board's clock moved on (a tick ended) or was set: every absorber may fire again. */
    void clockMoved() {
        fired.clear();
    }

    /** The gizmo performs its action: a flipper toggles, an absorber fires, a bumper only records the time. */
    void performAction(GizmoBase gizmo, double now) {
        gizmo.markTriggered(now);
        gizmo.act(this);
    }

    /**
     * A flipper that starts to swing wakes every ball in its box (its whole sweep lies there) and what rests on them.
     */
    @Override
    public void swung(Flipper flipper, boolean wasMoving) {
        if (flipper.isMoving() && !wasMoving) {
            recordEvent(new PlayEvent.Swing(flipper.name(), flipper.isActive()));
            wakeSweep(flipper);
        }
    }

    /** Wakes every ball in the moving shape's box, where all of its sweep lies, and what rests on them. */
    void wakeSweep(MovingShape moving) {
        double margin = 2 * Board.BALL_RADIUS;
        sleepers.wakeWithin(moving.x() - margin, moving.y() - margin, moving.x() + moving.width() + margin,
                moving.y() + moving.height() + margin);
    }

    /**
     * Shoots the longest-held ball straight up from just above the top edge, if the spot there is free (inside
     * the board, no gizmo or free ball in the way); otherwise the ball stays held. An absorber fires at most once a
     * tick: a ball it fires into a ball wedged against the wall above, or a flipper a hair above its mouth, comes
     * straight back, and an absorber that its own capture triggers would fire it again and again, at no time or a
     * few microseconds apart, thousands of times a tick.
     */
    @Override
    public void fire(Absorber absorber) {
        List<String> held = absorber.held();
        if (held.isEmpty()) {
            return;
        }
        String name = held.get(0);
        Vect launch = absorber.launchPosition(Board.BALL_RADIUS);
        if (fired.contains(absorber.name())) {
            return;   // fired already in this tick: what came straight back stays held until the next
        }
        if (rules.freeForBall(launch)) {
            fired.add(absorber.name());
            absorber.letGo(name);
            registry.ball(name).release(launch, new Vect(0, -Board.ABSORBER_LAUNCH_SPEED));
            recordEvent(new PlayEvent.Fired(absorber.name()));
            double margin = 4 * Board.BALL_RADIUS;
            sleepers.wakeWithin(launch.x() - margin, launch.y() - margin, launch.x() + margin, launch.y() + margin);
        }
    }

    /** Holds the ball at the absorber's bottom-right corner, at rest, behind any it already holds. */
    void capture(Ball ball, Absorber absorber) {
        ball.capture(absorber.holdingPosition(Board.BALL_RADIUS));
        absorber.hold(ball.name());
    }

    /** An absorber placed or moved captures the free balls it now covers. */
    void captureFreeBallsIn(Absorber absorber) {
        for (Ball ball : registry.balls()) {
            if (!ball.isCaptured() && Overlaps.ballInGizmo(absorber, ball.position())) {
                capture(ball, absorber);
            }
        }
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
}
