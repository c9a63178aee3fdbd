package gizmoball.model.loop;

import gizmoball.model.gizmo.BallTaking;
import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.MovingShape;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Function;

import physics.Vect;

/**
 * One tick of the six-stage loop on a board (docs/design.md, "The tick"). Stage 1 changes the velocities of the awake
 * balls; then stages 3 (detect, through a {@link CollisionSchedule} that asks again only about what the last
 * collision changed), 2 (move what moves to the collision), 4 (resolve) and 5 (trigger) repeat until the tick is
 * used up; stage 6 reports, and the board notifies its observers. In {@link LoopMode#SEED} a ball that has bounced
 * stays where it is for the rest of the tick (the classic loop: at most one collision per ball and tick); in
 * {@link LoopMode#CONTINUOUS} it goes on moving, so no time is lost.
 *
 * <p>This class runs the stages; stage 4's resolutions are jobs of their own, sharing the tick's {@link StepContext}:
 * {@link StillSurfaces} (bounces, resting contact, wedges), {@link BallPairs} (bounces and piles),
 * {@link ClusterSolve} (contacts solved at once) and {@link MovingStrikes} (what moving shapes strike).
 *
 * <p>Resting and rolling contact: a ball meeting a still surface more slowly than about two ticks of the gravity
 * pressing it into that surface loses its normal velocity instead of bouncing and keeps the surface as a persistent
 * contact ({@link Contacts}); from then on stage 1 removes the part of gravity pressing into it, so the ball rolls
 * along or lies on it with no collision at all. A ball lying still on its contacts for
 * {@link LoopSettings#sleepTime()} falls asleep: no gravity, no detection, no motion, until something can reach it
 * ({@link Sleepers}).
 *
 * <p>Energy: in CONTINUOUS mode the {@link ShadowEnergy} of the balls whose collisions were all elastic is kept.
 */
public final class TickRun {
    private final StepContext step;
    private final StillSurfaces still;
    private final BallPairs pairs;
    private final ClusterSolve clusters;
    private final MovingStrikes strikes;
    /** Nanoseconds of each stage in this tick, by {@link Stage#ordinal()}, if it times them ({@link #timing}). */
    private final long[] nanos = new long[Stage.values().length];
    private boolean timing;
    /**
     * Stage 1's books, kept from tick to tick: the gizmos that took a ball touching them, the gizmos near a ball, a
     * ball's contact normals.
     */
    private final List<GizmoBase> tookOnTouch = new ArrayList<>();
    private final List<GizmoBase> touched = new ArrayList<>();
    private final List<Vect> contactNormals = new ArrayList<>();
    /** The normals of a ball's contacts as they are now, for the shadow energy: made once, not every tick. */
    private final Function<Ball, List<Vect>> normalsNow;
    /** Stage 6: what the last tick did, kept until the next one ends. */
    private final TickEnd end;

    /**
     * The loop of the board that {@code view} shows and {@code actions} act on, tuned by {@code settings}, which the
     * board keeps and runs once per {@code Board.tick}; not for views. Its books last from tick to tick (each tick starts them empty), so a tick in
     * the steady state allocates little beyond its report.
     */
    public TickRun(LoopView view, LoopActions actions, LoopSettings settings) {
        this.step = new StepContext(view, actions, settings);
        this.still = new StillSurfaces(step);
        this.pairs = new BallPairs(step);
        this.clusters = new ClusterSolve(step);
        this.strikes = new MovingStrikes(step);
        this.normalsNow = ball -> step.contacts.normals(ball);
        this.end = new TickEnd(step, nanos);
    }

    /**
     * Runs one tick of {@code dt} seconds: the six stages. What stage 6 reports is read in place ({@link #events()},
     * {@link #guards()}) until the next tick, and {@link #report()} makes the report of it for whoever asks.
     */
    public void run(double dt) {
        timing = step.view.timesStages();
        long start = timing ? System.nanoTime() : 0;
        step.begin(dt);
        strikes.begin();
        Arrays.fill(nanos, 0);
        strikes.releaseStalled();
        stage1FrictionAndGravity();
        long mark = lap(Stage.FRICTION_AND_GRAVITY, start);
        step.findAwake();
        if (step.awake.isEmpty()) {
            // Nothing that moves can collide (a moving shape wakes what lies in its way before it reaches it): the
            // shapes turn, and the sleeping balls are not filed, so a pile asleep costs little more than the board.
            stage2BallMotion(step.dt);
            lap(Stage.BALL_MOTION, mark);
        } else {
            collide(mark);
        }
        if (step.view.loopMode() == LoopMode.CONTINUOUS) {
            step.energy.restore(normalsNow);   // SEED stays the classic loop, lost time and all
        }
        step.actions.forgetSeparatedPairs();
        step.actions.advanceTime(step.dt);
        end.take(timing);
        step.schedule.unfile();   // the balls keep their centres themselves between ticks
    }

    /** Stages 3, 2, 4 and 5 from collision to collision, to the end of the tick or the collision cap. */
    private void collide(long since) {
        long mark = since;
        step.schedule.file(step.freeBalls(), 0, step.dt);
        double remaining = step.dt;
        LoopSettings settings = step.settings;
        int maxCollisions = settings.maxCollisionsBase() + settings.maxCollisionsPerBall() * step.awake.size();
        while (remaining > 0) {
            Collision collision = stage3CollisionDetection(remaining);
            mark = lap(Stage.COLLISION_DETECTION, mark);
            if (collision == null) {
                stage2BallMotion(remaining);
                lap(Stage.BALL_MOTION, mark);
                break;
            }
            stage2BallMotion(collision.time());
            mark = lap(Stage.BALL_MOTION, mark);
            remaining -= collision.time();
            Struck hit = stage4CollisionResolution(collision);
            mark = lap(Stage.COLLISION_RESOLUTION, mark);
            if (hit instanceof TriggerSource source) {
                stage5Triggering(source);
            }
            for (int i = 0; i < step.alsoHit.size(); i++) {
                stage5Triggering(step.alsoHit.get(i));
            }
            step.alsoHit.clear();
            mark = lap(Stage.TRIGGERING, mark);
            if (step.view.loopMode() == LoopMode.SEED && finishes(collision)) {
                finish(collision);
            }
            if (++step.collisions >= maxCollisions) {
                step.capped++;   // guard of last resort: per-ball caps end every run of collisions before it
                break;
            }
            capBall(collision.ball());
            if (collision.otherBall() != null) {
                capBall(collision.otherBall());
            }
        }
    }

    /**
     * Stage 1: V_new = V_old * (1 - mu*dt - mu2*|V_old|*dt), then gravity; speed clamped to MAX_SPEED. A ball in
     * persistent contact loses what presses it into its surfaces; a ball still on them long enough falls asleep.
     */
    private void stage1FrictionAndGravity() {
        LoopView view = step.view;
        double dt = step.dt;
        // gravity.times(dt), and each velocity below, on components: the doubles the vectors would hold
        double kickX = step.gravity.x() * dt + 0.0;
        double kickY = step.gravity.y() * dt + 0.0;
        List<GizmoBase> took = tookOnTouch;
        took.clear();
        List<Ball> awake = step.awakeCopy();   // a pile asleep costs nothing here (design.md, "Sleeping")
        for (int b = 0; b < awake.size(); b++) {
            Ball ball = awake.get(b);
            if (takenOnTouch(ball, took)) {
                continue;
            }
            List<Vect> normals = contactNormals;
            step.contacts.refresh(ball, normals);
            double vx = ball.vx();
            double vy = ball.vy();
            double factor = Math.max(0, 1 - view.mu() * dt - view.mu2() * Components.length(vx, vy) * dt);
            double slowX = vx * factor + 0.0;   // v.times(factor)
            double slowY = vy * factor + 0.0;
            double freeX = slowX + kickX + 0.0;   // plus the kick
            double freeY = slowY + kickY + 0.0;
            int along = Projection.of(freeX, freeY, normals);
            boolean pressed = along != Projection.CLOSES_ON_NONE;
            double nextX = Projection.x(freeX, freeY, normals, along);
            double nextY = Projection.y(freeX, freeY, normals, along);
            ball.setVelocity(nextX, nextY);
            // a ball that only slides loses only the kick
            if (pressed && !Contacts.slidesOnStill(ball, slowX, slowY, normals)) {
                step.energy.lost(ball);
            } else if (Double.compare(ball.vx(), nextX) == 0 && Double.compare(ball.vy(), nextY) == 0) {
                step.energy.start(ball);
            }
            countStillness(ball, normals);
        }
        // Once every ball has its velocity: a trigger may add balls (a spawner) or wake them.
        for (int i = 0; i < took.size(); i++) {
            stage5Triggering(TriggerSource.gizmo(took.get(i).name()));
        }
    }

    /**
     * A ball that touches a gizmo that takes balls out of play (a sink) when the tick begins is taken, as one that
     * meets it during the tick is: a ball moving along its side or lying beside it never moves into it, so no
     * collision would ever take it.
     */
    private boolean takenOnTouch(Ball ball, List<GizmoBase> took) {
        if (!step.view.index().holdsRemovers()) {
            return false;   // no sink on the board: no ball asks the index
        }
        double x = ball.x();
        double y = ball.y();
        double reach = Arena.BALL_RADIUS + Tolerances.CONTACT;
        step.view.index().within(x - reach, y - reach, x + reach, y + reach, touched);
        for (int i = 0; i < touched.size(); i++) {
            GizmoBase gizmo = touched.get(i);
            if (gizmo.ballTaking() == BallTaking.REMOVES && gizmo.signedDistance(ball.position()) <= reach) {
                gizmo.markTriggered(step.now());
                still.take(ball, gizmo);
                took.add(gizmo);
                return true;
            }
        }
        return false;
    }

    private void countStillness(Ball ball, List<Vect> normals) {
        double stillFor = ball.stillTime() + step.dt;
        if (normals.isEmpty() || Components.length(ball.vx(), ball.vy()) > step.settings.sleepSpeed()
                || strikes.nearMoving(ball)) {
            ball.setStillTime(0);
        } else if (step.settings.stillLongEnough(stillFor, step.dt)) {
            ball.fallAsleep();
        } else {
            ball.setStillTime(stillFor);
        }
    }

    /** Stage 2: awake balls move in straight lines, moving shapes turn (stopping where they stop), for time t. */
    private void stage2BallMotion(double t) {
        if (t == 0) {
            return;   // a zero-time collision (a chain through touching balls): nothing moves, p + v*0 is p
        }
        step.moveBalls(t);
        List<MovingShape> shapes = step.view.movingShapes();
        for (int j = 0; j < shapes.size(); j++) {
            MovingShape moving = shapes.get(j);
            moving.advance(t);   // one at a stop, or stalled by a jammed ball, does not move
        }
        step.elapsed += t;
    }

    /** Stage 3: the earliest collision within the time left, or null. */
    private Collision stage3CollisionDetection(double window) {
        return step.schedule.next(step.awake, step.elapsed, window);
    }

    /**
     * Stage 4: the ball and what it hits touch now; a collision in a cluster of touching contacts is solved with
     * them all ({@link ClusterSolve}), else the ball reflects with the matching physics-lib method, comes to rest, or
     * is captured. Returns what was hit: a gizmo, the outer walls or a ball.
     */
    private Struck stage4CollisionResolution(Collision collision) {
        Ball ball = collision.ball();
        Contact contact = collision.contact();
        step.restingContact = false;
        step.reported.clear();
        ball.setStillTime(0);
        boolean chained = step.chained(collision);
        step.countTiming(chained, collision.time());
        ContactCluster cluster = clusters.toSolve(collision);
        if (cluster != null) {
            Struck hit = clusters.resolve(collision, cluster);
            forgetWhatChanged(collision);
            noteCollision(collision);
            return hit;
        }
        noteCollision(collision);
        Struck hit;
        if (contact instanceof Contact.MovingPart part) {
            hit = strikes.resolve(ball, part);
        } else if (contact instanceof Contact.OtherBall other) {
            strikes.met(ball, contact);
            strikes.met(other.other(), ball.asContact());
            hit = pairs.resolve(ball, other.other());
        } else {
            strikes.met(ball, contact);
            hit = still.resolve(ball, (Contact.StillSurface) contact);
        }
        forgetWhatChanged(collision);
        if (chained) {
            if (step.countZeroTimeHit(ball) > step.settings.zeroTimeHitsBeforeWedged()
                    && !(contact instanceof Contact.MovingPart)) {
                step.wedged++;   // guard (counted): at rest for the rest of this tick
                ball.setVelocity(Vect.ZERO);
                step.energy.lost(ball);
            }
        }
        return hit;
    }

    /** Stage 5: the gizmo or the walls that were hit trigger every gizmo connected to them, as each connection says. */
    private void stage5Triggering(TriggerSource source) {
        double now = step.now();
        List<Connection> connections = step.view.connectionsFrom(source);
        for (int i = 0; i < connections.size(); i++) {
            Connection connection = connections.get(i);
            GizmoBase target = step.view.gizmo(connection.target());
            if (target != null) {
                StepContext.BallCounts balls = step.ballCounts();
                step.actions.trigger(target, connection.order(), now);
                if (connection.order().delay() > 0) {
                    continue;   // nothing happens until the delay has run
                }
                if (target instanceof MovingShape moving) {
                    step.movingShapeChanged(moving);   // it turned round, or started, or flashed
                } else if (!step.ballCounts().equals(balls)) {
                    step.ballsChanged();   // an absorber fired a ball, and woke what lay by its mouth
                }
                // else it flashed, or its order waits for the tick's end (a gate or a drop target, a spawner)
            }
        }
    }

    /** The report of the last tick, made anew; the events' records are the caller's to keep. */
    public TickReport report() {
        return end.report();
    }

    /** The last tick's events, read in place until the next tick ends. */
    public TickEvents events() {
        return end.events();
    }

    /** The guards that fired in the last tick. */
    public GuardCounts guards() {
        return end.guards();
    }

    private long lap(Stage stage, long since) {
        if (!timing) {
            return since;
        }
        long now = System.nanoTime();
        nanos[stage.ordinal()] += now - since;
        return now;
    }

    private void noteCollision(Collision collision) {
        step.noteCollision(collision.ball());
        if (collision.otherBall() != null) {
            step.noteCollision(collision.otherBall());
        }
    }

    /** A ball over its own collision cap moves no more in this tick: the guard acts on it alone. */
    private void capBall(Ball ball) {
        if (step.countCollision(ball) == step.settings.maxCollisionsOfABall()) {
            step.capped++;
            step.finished.add(ball);
            step.energy.lost(ball);
            step.changed(ball);
        }
    }

    /** The balls of a resolved collision move differently now: stage 3 asks about them again. */
    private void forgetWhatChanged(Collision collision) {
        step.changed(collision.ball());
        if (collision.otherBall() != null) {
            step.changed(collision.otherBall());
        }
    }

    /**
     * SEED: whether the collision ends its balls' motion for the tick. A resting contact only projects the velocity:
     * no bounce to stop at; a ball a moving shape struck is carried on for the rest of the tick, or the shape would
     * turn into it where it stopped. Nor is a collision at the very start of the ball's motion: balls that stopped
     * where they touch would meet there again every tick, never moving apart, while gravity pumped their velocities
     * up.
     */
    private boolean finishes(Collision collision) {
        return !step.restingContact && !strikes.carries(collision.ball()) && step.elapsed > step.settings.zeroTime();
    }

    /** SEED: the ball (and a ball it hit) stays put for the rest of the tick. */
    private void finish(Collision collision) {
        step.finished.addBallsOf(collision);
    }
}
