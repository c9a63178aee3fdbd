package gizmoball.model.loop;

import gizmoball.model.gizmo.MovingShape;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

import physics.Vect;

/**
 * The state of one tick, shared by the jobs of a {@link TickRun} (as Box2D passes its step context): what the board
 * shows and lets the loop do, the tick's constants, the collision machinery, the balls' per-tick books and the
 * counters the report gives. The board's one {@link TickRun} keeps it from tick to tick, so that a tick allocates none
 * of its books (as Box2D's step takes its per-step memory from an arena): {@link #begin} empties every book and sets
 * the tick's constants; nothing in it carries from one tick to the next.
 */
final class StepContext {
    final LoopView view;
    final LoopActions actions;
    final LoopSettings settings;
    /** Seconds: the length of the tick. */
    double dt;
    /** Seconds of play at the start of the tick. */
    double startTime;
    /** L/s^2. */
    Vect gravity;
    /** The contact queries for this tick's gravity and length (made again only when either changes). */
    Contacts contacts;
    /** {@link #pressingSpeed()}, set with the gravity and length it is made of. */
    private double pressingSpeed;
    final ShadowEnergy energy;
    /** SEED: balls that have had their collision this tick and move no more; CONTINUOUS: balls over their cap. */
    final FinishedBalls finished = new FinishedBalls();
    final CollisionDetector detector;
    final CollisionSchedule schedule;
    /** The centres and motions of the balls the schedule filed: stage 2 moves them in one pass. */
    final Motions motions = new Motions();
    /** The balls that move in this tick: neither captured nor asleep. */
    final List<Ball> awake = new ArrayList<>();
    /** {@link #awakeCopy}'s list, kept from tick to tick. */
    private final List<Ball> awakeCopy = new ArrayList<>();
    /** Tick numbers, unique across every loop of the process, so that no ball's marks are taken for another tick's. */
    private static final AtomicLong TICKS = new AtomicLong();
    /**
     * This tick's number: what a ball's marks of the tick are stamped with ({@link Ball#collisionMarks}, and the shadow
     * energy's), so that nothing is emptied tick after tick.
     */
    long tick;
    /**
     * {@link Ball#stateChanges()} when {@link #awake} was last found, the board's list of balls it was found in (a ball
     * added or removed makes a new one) and how many of the free balls slept then: while neither changes, the awake
     * balls and the sleeping ones are those found, from tick to tick, so a pile asleep is not looked through again.
     */
    private long awakeFoundAt;
    private List<Ball> awakeFoundIn;
    private int asleepAtFind;
    /**
     * {@link Ball#stateChanges()} when {@link #ballCounts} were last found (a tick starts with none found: between
     * ticks balls are added and removed).
     */
    private BallCounts counts;
    private long countedAt;
    /** Surfaces hit besides the collision's own within the collision just resolved, for stage 5. */
    final List<TriggerSource> alsoHit = new ArrayList<>();
    /**
     * The surfaces whose hit the collision being resolved has reported: the bounces among a ball's contacts within one
     * collision (a wedge takes about 180 / its angle of them) are one hit each for the sound and the score. A list,
     * as there are a few at most: adding to it makes nothing, where a set makes an entry.
     */
    final List<ContactRef> reported = new ArrayList<>();
    /** Seconds of the tick simulated so far. */
    double elapsed;
    int collisions;
    int zeroTimeCollisions;
    int simultaneousCollisions;
    long wedged;
    long pinched;
    long capped;
    /** Whether the collision resolved last was a resting contact rather than a bounce. */
    boolean restingContact;

    /** Empty books for the board that {@code view} shows; {@link #begin} starts each tick. */
    StepContext(LoopView view, LoopActions actions, LoopSettings settings) {
        this.view = view;
        this.actions = actions;
        this.settings = settings;
        this.energy = new ShadowEnergy(settings);
        this.detector = new CollisionDetector(view, finished, settings);
        this.schedule = new CollisionSchedule(detector, view.ballGrid(), motions, settings);
    }

    /** A tick of {@code seconds} starts: the constants are the board's now, every book is empty, every count 0. */
    void begin(double seconds) {
        Vect boardGravity = view.gravity();
        if (contacts == null || seconds != dt || !boardGravity.equals(gravity)) {
            contacts = new Contacts(view, boardGravity, seconds);
            // gravity's length is a hypot, and two balls meeting asked for this at every bounce
            pressingSpeed = Math.max(Tolerances.ROUNDING_SPEED,
                    settings.restTicksOfGravity() * boardGravity.length() * seconds);
        }
        dt = seconds;
        startTime = view.time();
        gravity = boardGravity;
        tick = TICKS.incrementAndGet();
        energy.begin(gravity, dt, tick);
        schedule.begin(seconds);
        finished.clear();
        counts = null;
        alsoHit.clear();
        reported.clear();
        elapsed = 0;
        collisions = 0;
        zeroTimeCollisions = 0;
        simultaneousCollisions = 0;
        wedged = 0;
        pinched = 0;
        capped = 0;
        restingContact = false;
    }

    /** Seconds of play now, within the tick. */
    double now() {
        return startTime + elapsed;
    }

    /**
     * The ball left play (an absorber holds it, a sink took it): only what was going to meet it asks again; the
     * scene and every other ball's collisions stand.
     */
    void ballLeft(Ball ball) {
        findAwake();
        schedule.forget(ball);
    }

    /** How many balls are free and how many of them awake. */
    record BallCounts(int free, int awake) {
    }

    /**
     * The balls free and awake now: a trigger that changes neither count changes nothing the loop knows. Counted again
     * only when a ball's state may have changed since the last count ({@link Ball#stateChanges()}), so the triggers
     * of a tick's wall hits on a spawner board do not count 200 balls twice each.
     */
    BallCounts ballCounts() {
        long changes = Ball.stateChanges();
        if (counts != null && changes == countedAt) {
            return counts;
        }
        int free = 0;
        int awakeNow = 0;
        List<Ball> balls = view.balls();
        for (int b = 0; b < balls.size(); b++) {
            Ball ball = balls.get(b);
            if (!ball.isCaptured()) {
                free++;
                awakeNow += ball.isAsleep() ? 0 : 1;
            }
        }
        counts = new BallCounts(free, awakeNow);
        countedAt = changes;
        return counts;
    }

    /**
     * A moving shape changed how it moves (turned round, started, stopped, stalled on a ball): only the balls that can
     * reach its box in what is left of the tick can meet it otherwise than they were going to, so only their
     * collisions with the scene are asked again. The balls its sweep woke ask when the schedule next looks: they lie
     * still, as every known collision took them, so nothing else is asked again (filing every ball afresh at each
     * flipper a hit turned cost slow-200-balls.txt a third of its questions).
     */
    void movingShapeChanged(MovingShape moving) {
        findAwake();
        schedule.forgetReaching(moving.x(), moving.y(), moving.x() + moving.width(), moving.y() + moving.height(),
                dt - elapsed);
    }

    /**
     * A trigger freed balls (an absorber fired) or took them, and woke what lay near: a freed ball is filed where it
     * is now and asks when the schedule next looks, as do the balls woken; a taken one is forgotten, as
     * {@link #ballLeft} has it. A ball freed after it was taken in this filing (fired by the absorber that just caught
     * it) lies far from the cell it was filed in: it alone is filed afresh (filing every ball again at each such shot
     * cost slow-200-balls.txt a fifth of the questions of its first 150 ticks). Every other known collision stands
     * (the balls woken lie still, as they were taken).
     */
    void ballsChanged() {
        findAwake();
        List<Ball> balls = view.balls();
        for (int b = 0; b < balls.size(); b++) {
            Ball ball = balls.get(b);
            if (ball.isCaptured()) {
                schedule.forget(ball);
            } else if (schedule.wasTaken(ball)) {
                schedule.refile(ball, elapsed);
            } else if (!schedule.isFiled(ball)) {
                schedule.add(ball, elapsed);
            }
        }
    }

    /**
     * The ball went where its motion did not take it (a portal moved it), and woke what lay near: only what was to
     * meet it asks again, and it is filed afresh where it is; the scene and every other known collision stand.
     */
    void ballMoved(Ball ball) {
        findAwake();
        schedule.forget(ball);
        schedule.refile(ball, elapsed);
    }

    /**
     * Every awake ball straight on for {@code t} seconds, but for the finished ones: in one pass over the filed balls'
     * {@link Motions} (the sleeping ones still there), or one by one where some have finished (SEED) or none is filed.
     */
    void moveBalls(double t) {
        boolean anyFinished = !finished.isEmpty();
        if (motions.isUsed() && !anyFinished) {
            motions.advance(t);
            return;
        }
        for (int i = 0, n = awake.size(); i < n; i++) {
            Ball ball = awake.get(i);
            if (!anyFinished || !finished.contains(ball)) {
                ball.advance(t);
            }
        }
    }

    /** The awake balls, found again only when a ball's state may have changed since they were last found. */
    void findAwake() {
        long changes = Ball.stateChanges();
        List<Ball> balls = view.balls();
        if (awakeFoundIn == balls && changes == awakeFoundAt) {
            return;
        }
        awakeFoundIn = balls;
        awakeFoundAt = changes;
        schedule.awakeChanged();
        awake.clear();
        int asleep = 0;
        for (int b = 0; b < balls.size(); b++) {
            Ball ball = balls.get(b);
            if (ball.isCaptured()) {
                continue;
            }
            if (ball.isAsleep()) {
                asleep++;
            } else {
                awake.add(ball);
            }
        }
        asleepAtFind = asleep;
    }

    /**
     * The awake balls now, in board order, in a list of their own that stays as it is while they are gone through: a
     * ball taken by a sink it touches finds the awake balls again ({@link #ballLeft}), and going on through that list
     * would skip the next ball.
     */
    List<Ball> awakeCopy() {
        findAwake();
        awakeCopy.clear();
        for (int i = 0; i < awake.size(); i++) {   // by index: addAll would make an array of them each tick
            awakeCopy.add(awake.get(i));
        }
        return awakeCopy;
    }

    /** How many of the free balls sleep now: as {@link #findAwake} last found, unless a ball's state changed since. */
    int asleepNow() {
        List<Ball> balls = view.balls();
        if (awakeFoundIn == balls && Ball.stateChanges() == awakeFoundAt) {
            return asleepAtFind;
        }
        int asleep = 0;
        for (int b = 0; b < balls.size(); b++) {
            Ball ball = balls.get(b);
            asleep += !ball.isCaptured() && ball.isAsleep() ? 1 : 0;
        }
        return asleep;
    }

    /** The balls no absorber holds, in board order (a list kept for the tick's filings). */
    List<Ball> freeBalls() {
        free.clear();
        List<Ball> balls = view.balls();
        for (int b = 0; b < balls.size(); b++) {
            Ball ball = balls.get(b);
            if (!ball.isCaptured()) {
                free.add(ball);
            }
        }
        return free;
    }

    private final List<Ball> free = new ArrayList<>();

    /** The ball moves differently now: stage 3 asks about it again. */
    void changed(Ball ball) {
        schedule.forget(ball);
        schedule.sped(ball, elapsed);
    }

    /** The ball keeps the surface as a contact and loses every part of its velocity that presses into its contacts. */
    void comeToRest(Ball ball, ContactRef ref) {
        Contacts.attach(ball, ref);
        List<Vect> normals = contacts.normals(ball);
        int along = Projection.of(ball.vx(), ball.vy(), normals);   // Contacts.project, on the components
        if (along != Projection.CLOSES_ON_NONE) {
            ball.setVelocity(Projection.x(ball.vx(), ball.vy(), normals, along),
                    Projection.y(ball.vx(), ball.vy(), normals, along));
        }
        energy.lost(ball);
        restingContact = true;
    }

    /**
     * L/s: a ball approaching a surface with this normal, while its other contacts have these normals, more slowly
     * than this is resting contact: {@link LoopSettings#restTicksOfGravity()} ticks of the acceleration pressing it
     * into the surface, which is gravity as the other contacts leave it (a ball on a slope is pressed into the wall at
     * its foot by the slope, though gravity is parallel to the wall).
     */
    double restingSpeed(Vect normal, List<Vect> otherNormals) {
        // Contacts.project(gravity, otherNormals), on the components
        int along = Projection.of(gravity.x(), gravity.y(), otherNormals);
        boolean free = along == Projection.CLOSES_ON_NONE;
        double pullX = free ? gravity.x() : Projection.x(gravity.x(), gravity.y(), otherNormals, along);
        double pullY = free ? gravity.y() : Projection.y(gravity.x(), gravity.y(), otherNormals, along);
        double pressing = Math.max(0, -(pullX * normal.x() + pullY * normal.y()));
        return Math.max(Tolerances.ROUNDING_SPEED, settings.restTicksOfGravity() * pressing * dt);
    }

    /** L/s: two balls meeting more slowly than this, one of them held, press together (gravity's ticks' worth). */
    double pressingSpeed() {
        return pressingSpeed;
    }

    GuardCounts guards() {
        return wedged + pinched + capped == 0 ? GuardCounts.NONE : new GuardCounts(wedged, pinched, capped);
    }

    /**
     * Whether the collision continues a chain: its ball, or the ball it meets, had a collision of its own at this
     * very moment (within {@link LoopSettings#zeroTime()}). Balls apart that collide at the same instant are not a
     * chain: each is the first of its own.
     */
    boolean chained(Collision collision) {
        Ball other = collision.otherBall();
        return recentlyCollided(collision.ball()) || other != null && recentlyCollided(other);
    }

    private boolean recentlyCollided(Ball ball) {
        Ball.CollisionMarks marks = ball.collisionMarks(tick);
        return marks.collided && elapsed - marks.lastAt <= settings.zeroTime();
    }

    /** The ball's collision was resolved now. */
    void noteCollision(Ball ball) {
        Ball.CollisionMarks marks = ball.collisionMarks(tick);
        marks.collided = true;
        marks.lastAt = elapsed;
    }

    /** When its last collision of the tick was resolved, in seconds since the tick began; NaN: none yet. */
    double lastCollisionAt(Ball ball) {
        Ball.CollisionMarks marks = ball.collisionMarks(tick);
        return marks.collided ? marks.lastAt : Double.NaN;
    }

    /** The ball's collisions in this tick so far. */
    int collisionsOf(Ball ball) {
        return ball.collisionMarks(tick).collisions;
    }

    /** Counts one more collision of the ball in this tick; returns how many it has had. */
    int countCollision(Ball ball) {
        return ++ball.collisionMarks(tick).collisions;
    }

    /** Counts one more collision of the ball at zero time in this tick; returns how many it has had. */
    int countZeroTimeHit(Ball ball) {
        return ++ball.collisionMarks(tick).zeroTimeHits;
    }

    /** Counts a collision, found {@code after} seconds past the one before it, as chained, simultaneous or neither. */
    void countTiming(boolean chained, double after) {
        if (chained) {
            zeroTimeCollisions++;
        } else if (after <= settings.zeroTime()) {
            simultaneousCollisions++;
        }
    }
}
