package gizmoball.model.loop;

import gizmoball.model.gizmo.Absorber;
import gizmoball.model.gizmo.Flipper;
import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Shape;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.DoubleFunction;

import physics.Circle;
import physics.Geometry;
import physics.LineSegment;
import physics.Vect;

/**
 * One tick of the six-stage loop on a board (docs/design.md, "The tick"). Stage 1 changes the velocities of the awake
 * balls; then stages 3 (detect, through a {@link CollisionSchedule} that asks again only about what the last
 * collision changed), 2 (move what moves to the collision), 4 (resolve) and 5 (trigger) repeat until the tick is
 * used up; stage 6 reports, and the board notifies its observers. In {@link LoopMode#SEED} a ball that has bounced
 * stays where it is for the rest of the tick (the classic loop: at most one collision per ball and tick); in
 * {@link LoopMode#CONTINUOUS} it goes on moving, so no time is lost.
 *
 * <p>Resting and rolling contact: a ball meeting a still surface more slowly than about two ticks of the gravity
 * pressing it into that surface loses its normal velocity instead of bouncing and keeps the surface as a persistent
 * contact ({@link Contacts}); from then on stage 1 removes the part of gravity pressing into it, so the ball rolls
 * along or lies on it with no collision at all. A ball lying still on its contacts for {@link #SLEEP_TICKS} ticks
 * falls asleep: no gravity, no detection, no motion, until something can reach it ({@link Sleepers}).
 *
 * <p>Energy: in CONTINUOUS mode the {@link ShadowEnergy} of the balls whose collisions were all elastic is kept.
 *
 * <p>At about 700 lines this class is over the project's 400: the six stages and the resolution of each kind of
 * contact (bounces, resting, wedges, piles, strikes and squeezes of a swinging flipper) read best together, since each
 * resolution feeds the stage counters and the energy book; the parts with a life of their own (contacts, sleepers,
 * energy, the schedule) are classes of their own.
 */
public final class TickRun {
    /** A collision sooner than this after the previous one counts as zero-time. */
    static final double ZERO_TIME = 1e-12;
    /** Slower normal approach than this many ticks' worth of the gravity pressing into a surface is resting contact. */
    static final double REST_TICKS_OF_GRAVITY = 2;
    /** L/s: a ball on its contacts slower than this is still. */
    static final double SLEEP_SPEED = 1e-3;
    /** Ticks a ball must lie still on its contacts before it falls asleep. */
    static final int SLEEP_TICKS = 30;
    private static final int ZERO_TIME_HITS_BEFORE_WEDGED = 32;
    /** A flipper striking the same ball this often in one tick, after it came back from something, squeezes it. */
    private static final int STRIKES_OF_A_SQUEEZE = 2;
    /** A flipper striking the same ball this often in one tick, nothing in between, is pushing it. */
    private static final int STRIKES_OF_A_PUSH = 3;
    /** Squeezes of one ball in one tick, each sending it out between a flipper and what it came back from. */
    private static final int SQUEEZES_BEFORE_PINCHED = 16;
    /** Bounces among a ball's contacts in one collision: enough to leave a wedge of a hundredth of a degree. */
    private static final int BOUNCES_AMONG_CONTACTS = 20_000;
    /** Enough for the pair's velocities to settle to rounding: each step shrinks their closing several times. */
    private static final int PRESS_STEPS = 64;
    private static final int MAX_COLLISIONS_BASE = 500;
    private static final int MAX_COLLISIONS_PER_BALL = 100;
    /**
     * Collisions of one ball in one tick after which it moves no more in this tick (a guard, counted): it stops
     * only itself, never a ball elsewhere on the board.
     */
    private static final int MAX_COLLISIONS_OF_A_BALL = 400;
    /** Collisions of a ball in one tick, each soon after the last, that make it a rattle solved as a cluster. */
    private static final int RATTLE_COLLISIONS = 8;
    /** Seconds: collisions of one ball this close together are a rattle. */
    private static final double RATTLE_TIME = 1e-3;
    /** L: the farthest a rattling ball's cluster reaches for what it nearly touches. */
    private static final double RATTLE_REACH = 1e-3;

    /** A ball and a flipper, for counting how often the flipper hits the ball within one tick. */
    private record Strike(Ball ball, Flipper flipper) {
    }

    private final LoopView view;
    private final LoopActions actions;
    private final double dt;
    private final double startTime;
    private final double gravity;
    private final Contacts contacts;
    /** SEED: balls that have had their collision this tick and move no more. */
    private final Set<Ball> finished = new HashSet<>();
    /** SEED: balls a swinging flipper struck this tick, which move on to the end of it. */
    private final Set<Ball> carried = new HashSet<>();
    private final CollisionDetector detector;
    private final CollisionSchedule schedule;
    private final List<Flipper> flippers;
    private final List<Ball> awake = new ArrayList<>();
    private final Map<Ball, Integer> zeroTimeHits = new HashMap<>();
    /** When, in seconds since the tick began, each ball's last collision of this tick was resolved. */
    private final Map<Ball, Double> lastCollisionAt = new HashMap<>();
    /** Collisions each ball has had in this tick, for the local collision cap. */
    private final Map<Ball, Integer> collisionsOf = new HashMap<>();
    private final Map<Strike, Integer> strikes = new HashMap<>();
    /** Balls that met something else since a swinging flipper last struck them in this tick (struck balls only). */
    private final Set<Ball> metSinceStrike = new HashSet<>();
    /** What each ball struck by a swinging flipper in this tick has met since then, other than swinging flippers. */
    private final Map<Ball, Set<Contact>> metAfterStrike = new HashMap<>();
    /** The part of a swinging flipper that last struck each ball in this tick. */
    private final Map<Ball, Contact.SwingingPart> lastStrike = new HashMap<>();
    /** How often a squeeze has sent each ball out between a flipper and what it came back from, in this tick. */
    private final Map<Ball, Integer> squeezed = new HashMap<>();
    /** Surfaces a ball bounced off among its contacts within the collision just resolved, for stage 5. */
    private final List<TriggerSource> alsoHit = new ArrayList<>();
    /**
     * The surfaces whose hit the collision being resolved has reported: the bounces among a ball's contacts within one
     * collision (a wedge takes about 180 / its angle of them) are one hit each for the sound and the score.
     */
    private final Set<ContactRef> reported = new HashSet<>();
    private final ShadowEnergy energy;
    private final EnumMap<Stage, Long> nanos = new EnumMap<>(Stage.class);
    private double elapsed;
    private int collisions;
    private int zeroTimeCollisions;
    private long wedged;
    private long pinched;
    private long capped;
    /** Whether the collision stage 4 resolved last was a resting contact rather than a bounce. */
    private boolean restingContact;

    /**
     * A tick of {@code dt} seconds on the board that {@code view} shows and {@code actions} act on. For the board,
     * which runs one per {@code Board.tick}; not for views.
     */
    public TickRun(LoopView view, LoopActions actions, double dt) {
        this.view = view;
        this.actions = actions;
        this.dt = dt;
        this.startTime = view.time();
        this.gravity = view.gravity();
        this.contacts = new Contacts(view, dt);
        this.energy = new ShadowEnergy(gravity, dt, view.balls().size());
        this.detector = new CollisionDetector(view, finished);
        this.schedule = new CollisionSchedule(detector, view.ballGrid());
        this.flippers = view.flippers();
    }

    /** A blocked flipper goes on once no ball touches it any more. */
    private void releaseBlockedFlippers() {
        for (Flipper flipper : flippers) {
            if (flipper.isBlocked() && view.balls().stream().noneMatch(ball -> !ball.isCaptured()
                    && flipper.signedDistance(ball.position()) <= Arena.BALL_RADIUS + Tolerances.CONTACT)) {
                flipper.unblock();
                actions.wakeSweep(flipper);   // it swings on into whatever fell asleep in its way
            }
        }
    }

    /** Runs the tick once: the six stages, then the report for the board to keep. */
    public TickReport run() {
        long start = System.nanoTime();
        releaseBlockedFlippers();
        stage1FrictionAndGravity();
        long mark = lap(Stage.FRICTION_AND_GRAVITY, start);
        findAwake();
        schedule.file(freeBalls(), 0);
        double remaining = dt;
        int maxCollisions = MAX_COLLISIONS_BASE + MAX_COLLISIONS_PER_BALL * awake.size();
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
            for (TriggerSource source : alsoHit) {
                stage5Triggering(source);
            }
            alsoHit.clear();
            mark = lap(Stage.TRIGGERING, mark);
            if (view.loopMode() == LoopMode.SEED && finishes(collision)) {
                finish(collision);
            }
            if (++collisions >= maxCollisions) {
                capped++;   // guard of last resort: per-ball caps end every run of collisions before it
                break;
            }
            capBall(collision.ball());
            if (collision.contact() instanceof Contact.OtherBall other) {
                capBall(other.other());
            }
        }
        if (view.loopMode() == LoopMode.CONTINUOUS) {
            energy.restore();   // SEED stays the classic loop, lost time and all
        }
        actions.forgetSeparatedPairs();
        actions.advanceTime(dt);
        return report();
    }

    /**
     * Stage 1: V_new = V_old * (1 - mu*dt - mu2*|V_old|*dt), then gravity; speed clamped to MAX_SPEED. A ball in
     * persistent contact loses what presses it into its surfaces; a ball still on them long enough falls asleep.
     */
    private void stage1FrictionAndGravity() {
        for (Ball ball : view.balls()) {
            if (ball.isCaptured() || ball.isAsleep()) {
                continue;
            }
            List<Vect> normals = contacts.refresh(ball);
            Vect v = ball.velocity();
            double factor = Math.max(0, 1 - view.mu() * dt - view.mu2() * v.length() * dt);
            Vect free = v.times(factor).plus(new Vect(0, gravity * dt));
            Vect next = Contacts.project(free, normals);
            ball.setVelocity(next);
            if (next != free) {   // project gives back its argument when nothing presses
                energy.lost(ball);
            } else if (ball.velocity().equals(next)) {
                energy.start(ball);
            }
            countStillness(ball, normals);
        }
    }

    private void countStillness(Ball ball, List<Vect> normals) {
        if (normals.isEmpty() || ball.velocity().length() > SLEEP_SPEED || nearSwingingFlipper(ball)) {
            ball.setStillTicks(0);
        } else if (ball.stillTicks() + 1 >= SLEEP_TICKS) {
            ball.fallAsleep();
        } else {
            ball.setStillTicks(ball.stillTicks() + 1);
        }
    }

    private boolean nearSwingingFlipper(Ball ball) {
        double r = 2 * Arena.BALL_RADIUS;
        Vect p = ball.position();
        for (Flipper flipper : flippers) {
            if (flipper.isMoving() && p.x() > flipper.x() - r && p.x() < flipper.x() + flipper.width() + r
                    && p.y() > flipper.y() - r && p.y() < flipper.y() + flipper.height() + r) {
                return true;
            }
        }
        return false;
    }

    /** Stage 2: awake balls move in straight lines, swinging flippers turn (stopping at their limits), for time t. */
    private void stage2BallMotion(double t) {
        if (t == 0) {
            return;   // a zero-time collision (a chain through touching balls): nothing moves, p + v*0 is p
        }
        boolean anyFinished = !finished.isEmpty();
        for (int i = 0, n = awake.size(); i < n; i++) {
            Ball ball = awake.get(i);
            if (!anyFinished || !finished.contains(ball)) {
                ball.advance(t);
            }
        }
        for (Flipper flipper : flippers) {
            flipper.advance(t);   // one at a stop, or blocked by a jammed ball, does not move
        }
        elapsed += t;
    }

    /** Stage 3: the earliest collision within the time left, or null. */
    private Collision stage3CollisionDetection(double window) {
        return schedule.next(awake, elapsed, window);
    }

    /**
     * Stage 4: the ball and what it hits touch now; reflect with the matching physics-lib method, come to rest on
     * it, or be captured. Returns what was hit: a gizmo, the outer walls or a ball.
     */
    private Struck stage4CollisionResolution(Collision collision) {
        Ball ball = collision.ball();
        Contact contact = collision.contact();
        restingContact = false;
        reported.clear();
        ball.setStillTicks(0);
        ContactCluster cluster = clusterToSolve(collision);
        if (cluster != null) {
            Struck hit = resolveCluster(collision, cluster);
            forgetWhatChanged(collision);
            noteCollision(collision);
            if (collision.time() <= ZERO_TIME) {
                zeroTimeCollisions++;
            }
            return hit;
        }
        noteCollision(collision);
        if (!(contact instanceof Contact.SwingingPart)) {
            met(ball, contact);
            if (contact instanceof Contact.OtherBall other) {
                met(other.other(), new Contact.OtherBall(ball));
            }
        }
        Struck hit;
        if (contact instanceof Contact.OuterWall wall) {
            hitStill(ball, wall, null, normalFromSegment(ball, wall.segment()),
                    coeff -> Geometry.reflectWall(wall.segment(), ball.velocity(), coeff));
            hit = TriggerSource.OUTER_WALLS;
        } else if (contact instanceof Contact.Face face) {
            hit = hitGizmo(ball, face, face.gizmo(), normalFromSegment(ball, face.segment()),
                    coeff -> Geometry.reflectWall(face.segment(), ball.velocity(), coeff));
        } else if (contact instanceof Contact.Round round) {
            Vect centre = round.circle().getCenter();
            hit = hitGizmo(ball, round, round.gizmo(), ball.position().minus(centre).unitSize(),
                    coeff -> Geometry.reflectCircle(centre, ball.position(), ball.velocity(), coeff));
        } else if (contact instanceof Contact.SwingingPart part) {
            hit = hitSwingingFlipper(ball, part);
        } else {
            hit = hitBall(ball, ((Contact.OtherBall) contact).other());
        }
        forgetWhatChanged(collision);
        if (collision.time() <= ZERO_TIME) {
            zeroTimeCollisions++;
            if (zeroTimeHits.merge(ball, 1, Integer::sum) > ZERO_TIME_HITS_BEFORE_WEDGED
                    && !(contact instanceof Contact.SwingingPart)) {
                wedged++;   // guard (counted): at rest for the rest of this tick
                ball.setVelocity(Vect.ZERO);
                energy.lost(ball);
            }
        }
        return hit;
    }

    private static Vect normalFromSegment(Ball ball, LineSegment segment) {
        return ball.position().minus(Geometry.perpendicularPointWholeLine(segment, ball.position())).unitSize();
    }

    private TriggerSource hitGizmo(Ball ball, Contact contact, GizmoBase gizmo, Vect normal,
                                   DoubleFunction<Vect> reflect) {
        gizmo.markTriggered(now());
        if (gizmo instanceof Absorber absorber) {
            actions.recordEvent(new PlayEvent.Captured(absorber.name(), ball.name(), ball.position()));
            actions.capture(ball, absorber);
            energy.lost(ball);
            sceneChanged();
        } else {
            hitStill(ball, contact, gizmo, normal, reflect);
        }
        return TriggerSource.gizmo(gizmo.name());
    }

    /**
     * A still surface: a bounce with its coefficient or, approaching more slowly than the gravity pressing the ball
     * into it would explain, resting contact.
     */
    private void hitStill(Ball ball, Contact contact, GizmoBase gizmo, Vect normal, DoubleFunction<Vect> reflect) {
        ContactRef surface = Contacts.refOf(contact);
        if (bounceOff(ball, surface, gizmo, normal, reflect)) {
            bounceAmongContacts(ball, surface);
        }
    }

    /** Resting contact or a bounce off a still surface; true if the ball bounced. */
    private boolean bounceOff(Ball ball, ContactRef surface, GizmoBase gizmo, Vect normal,
                              DoubleFunction<Vect> reflect) {
        double approach = -ball.velocity().dot(normal);
        if (approach <= restingSpeed(ball, normal, surface)) {
            comeToRest(ball, surface);
            return false;
        }
        double coefficient = gizmo == null ? 1.0 : gizmo.reflectionCoefficient();
        Vect bounced = reflect.apply(coefficient);
        if (wedged(ball, surface, normal, bounced)) {
            comeToRest(ball, surface);
            return false;
        }
        if (reported.add(surface)) {   // a bounce, not a rest: one hit per surface and collision
            actions.recordEvent(new PlayEvent.Hit(gizmo == null ? TriggerSource.OUTER_WALLS
                    : TriggerSource.gizmo(gizmo.name()), gizmo == null ? null : gizmo.kind(), approach, ball.name(),
                    ball.position()));
        }
        ball.setVelocity(bounced);
        energy.bounced(ball, normal, coefficient == 1.0);
        return true;
    }

    /**
     * A ball that has bounced off one still surface into another it lies on (a contact) meets it at once, and then
     * the first again: in a narrow wedge an elastic ball turns back only after about 180 / (the wedge's angle in
     * degrees) such bounces. They are the same bounces the loop would find one at a time at no time apart, resolved
     * here, each one a hit that triggers as any hit does (stage 5 takes them after this collision's own).
     */
    private void bounceAmongContacts(Ball ball, ContactRef from) {
        List<ContactRef> among = new ArrayList<>(ball.contacts());
        if (!among.contains(from)) {
            among.add(from);   // met just now, not lain on: the ball may come straight back to it
        }
        ContactRef last = from;
        for (int bounce = 0; bounce < BOUNCES_AMONG_CONTACTS; bounce++) {
            Contacts.Touch next = contacts.closing(ball, among, last);
            if (next == null) {
                return;
            }
            collisions++;
            zeroTimeCollisions++;
            GizmoBase gizmo = next.gizmo();
            if (gizmo != null) {
                gizmo.markTriggered(now());
            }
            alsoHit.add(gizmo == null ? TriggerSource.OUTER_WALLS : TriggerSource.gizmo(gizmo.name()));
            if (!bounceOff(ball, next.ref(), gizmo, next.normal(), next.reflect())) {
                return;
            }
            last = next.ref();
        }
        wedged++;   // guard (counted): bounces that do not end; at rest for the rest of this tick
        ball.setVelocity(Vect.ZERO);
        energy.lost(ball);
    }

    /**
     * Whether the bounce off a surface only wedges the ball between it and what it lies on: those contacts take the
     * bounce as resting contact (it meets each of them more slowly than it would bounce off), and what they leave of it
     * still closes on the surface. Bouncing would go on in turn between the two without end, each time slower; it ends
     * where the ball rests against both. A bounce fast enough to leave a contact is a bounce like any other.
     */
    private boolean wedged(Ball ball, ContactRef surface, Vect normal, Vect bounced) {
        List<Vect> taking = new ArrayList<>();
        for (ContactRef ref : ball.contacts()) {
            Vect held = ref.equals(surface) ? null : contacts.normal(ball, ref);
            if (held != null) {
                if (-bounced.dot(held) > restingSpeed(ball, held, ref)) {
                    return false;
                }
                taking.add(held);
            }
        }
        return !taking.isEmpty() && Contacts.project(bounced, taking).dot(normal) < -Tolerances.ROUNDING_SPEED;
    }

    /** The ball met a surface other than a swinging flipper: noted only for a ball a flipper has struck. */
    private void met(Ball ball, Contact surface) {
        Set<Contact> met = metAfterStrike.isEmpty() ? null : metAfterStrike.get(ball);
        if (met != null) {
            metSinceStrike.add(ball);
            met.add(surface);
        }
    }

    /** The ball keeps the surface as a contact and loses every part of its velocity that presses into its contacts. */
    private void comeToRest(Ball ball, ContactRef ref) {
        Contacts.attach(ball, ref);
        ball.setVelocity(Contacts.project(ball.velocity(), contacts.normals(ball)));
        energy.lost(ball);
        restingContact = true;
    }

    /**
     * The ball approaching a surface with this normal more slowly than this is resting contact: two ticks of the
     * acceleration pressing it into the surface, which is gravity as the ball's other contacts leave it (a ball on a
     * slope is pressed into the wall at its foot by the slope, though gravity is parallel to the wall).
     */
    private double restingSpeed(Ball ball, Vect normal, ContactRef surface) {
        Vect pull = Contacts.project(new Vect(0, gravity), contacts.normalsBesides(ball, surface));
        double pressing = Math.max(0, -pull.dot(normal));
        return Math.max(Tolerances.ROUNDING_SPEED, REST_TICKS_OF_GRAVITY * pressing * dt);
    }

    private TriggerSource hitSwingingFlipper(Ball ball, Contact.SwingingPart part) {
        Flipper flipper = part.flipper();
        flipper.markTriggered(now());
        energy.lost(ball);
        finished.remove(ball);   // SEED too: a swinging flipper carries the ball on, it cannot stand in its way
        carried.add(ball);
        Shape shape = flipper.shape();
        double omega = flipper.angularVelocity();
        Vect pivot = flipper.pivot();
        Circle circle = ball.circle();
        Vect before = ball.velocity();
        Contact.SwingingPart previous = lastStrike.put(ball, part);
        if (previous != null && previous.flipper() != flipper) {
            met(ball, previous);   // struck by another flipper since: it came back from that one
        }
        boolean cameBack = metSinceStrike.remove(ball);
        Set<Contact> met = metAfterStrike.computeIfAbsent(ball, struck -> new LinkedHashSet<>());
        int strike = strikes.merge(new Strike(ball, flipper), 1, Integer::sum);
        Vect reflected = strike >= STRIKES_OF_A_PUSH && !cameBack
                ? pushed(before, reflectOffSwinging(part, shape, pivot, omega, circle, Vect.ZERO))
                : reflectOffSwinging(part, shape, pivot, omega, circle, before);
        boolean squeezedOut = strike >= STRIKES_OF_A_SQUEEZE && cameBack;
        boolean endless = squeezedOut && squeezed.merge(ball, 1, Integer::sum) > SQUEEZES_BEFORE_PINCHED;
        Optional<Vect> leaving = squeezedOut && !endless
                ? Squeeze.leaving(reflected, squeezeSides(ball, part, shape, pivot, omega, met, reflected))
                : Optional.of(reflected);
        ball.setVelocity(endless ? Vect.ZERO : leaving.orElse(Vect.ZERO));
        actions.recordEvent(new PlayEvent.Hit(TriggerSource.gizmo(flipper.name()), flipper.kind(),
                ball.velocity().minus(before).length() / 2, ball.name(), ball.position()));
        if (endless) {
            pinched++;   // guard (counted): squeezed out and back again without end
            stall(ball, flipper);
        } else if (leaving.isEmpty()) {
            actions.recordEvent(new PlayEvent.Jammed(flipper.name(), ball.name()));
            stall(ball, flipper);
        }
        return TriggerSource.gizmo(flipper.name());
    }

    /**
     * What a squeezed ball must leave: the flipper where it strikes, what the ball lies on, and everything it has met
     * since the flipper first struck it in this tick, each taken where the ball is now.
     */
    private List<Squeeze.Side> squeezeSides(Ball ball, Contact.SwingingPart part, Shape shape, Vect pivot,
                                            double omega, Set<Contact> met, Vect reflected) {
        List<Squeeze.Side> sides = new ArrayList<>();
        // The striking flipper: the ball must leave it at least as fast along the normal as its bounce does. Leaving
        // at only the surface's own speed would keep the ball on a surface that turns, and so speeds up under it
        // further out: struck again at once, without end.
        Squeeze.Side striking = flipperSide(ball, part, shape, pivot, omega);
        sides.add(new Squeeze.Side(striking.normal(),
                Math.max(striking.speed(), reflected.dot(striking.normal()))));
        contacts.normals(ball).forEach(normal -> sides.add(new Squeeze.Side(normal, 0)));
        met.forEach(surface -> sides.add(sideOf(ball, surface)));
        return sides;
    }

    /**
     * A part of a swinging flipper, taken where the ball is now, as a side of a {@link Squeeze}: its normal and the
     * speed of its surface along it there.
     */
    private static Squeeze.Side flipperSide(Ball ball, Contact.SwingingPart part, Shape shape, Vect pivot,
                                            double omega) {
        Vect normal = part.circle()
                ? ball.position().minus(shape.circles().get(part.index()).getCenter()).unitSize()
                : normalFromSegment(ball, shape.segments().get(part.index()));
        Vect touching = ball.position().minus(normal.times(Arena.BALL_RADIUS));
        return new Squeeze.Side(normal, CollisionDetector.surfaceVelocity(pivot, omega, touching).dot(normal));
    }

    /** A surface the ball came back from, taken where the ball is now, as a side of a {@link Squeeze}. */
    private Squeeze.Side sideOf(Ball ball, Contact surface) {
        if (surface instanceof Contact.SwingingPart part) {
            Flipper other = part.flipper();
            return flipperSide(ball, part, other.shape(), other.pivot(), other.angularVelocity());
        }
        if (surface instanceof Contact.OtherBall other) {
            Vect normal = ball.position().minus(other.other().position()).unitSize();
            return new Squeeze.Side(normal, detector.motion(other.other()).dot(normal));
        }
        if (surface instanceof Contact.Round round) {
            return new Squeeze.Side(ball.position().minus(round.circle().getCenter()).unitSize(), 0);
        }
        LineSegment segment = surface instanceof Contact.Face face ? face.segment()
                : ((Contact.OuterWall) surface).segment();
        return new Squeeze.Side(normalFromSegment(ball, segment), 0);
    }

    private static Vect reflectOffSwinging(Contact.SwingingPart part, Shape shape, Vect pivot, double omega,
                                           Circle circle, Vect velocity) {
        double coefficient = part.flipper().reflectionCoefficient();
        return part.circle()
                ? Geometry.reflectRotatingCircle(shape.circles().get(part.index()), pivot, omega, circle, velocity,
                        coefficient)
                : Geometry.reflectRotatingWall(shape.segments().get(part.index()), pivot, omega, circle, velocity,
                        coefficient);
    }

    /**
     * A ball the flipper keeps striking with nothing in between is being pushed: each bounce leaves it a little
     * slower than the surface further out, which meets it again at once, without end. It is batted as a ball at
     * rest would be (the normal velocity a still ball would take), keeping its sliding along the surface, and so
     * leaves the surface for good.
     */
    private static Vect pushed(Vect before, Vect fromRest) {
        double speed = fromRest.length();
        if (speed == 0) {
            return before;
        }
        Vect normal = fromRest.times(1 / speed);
        return before.minus(normal.times(before.dot(normal))).plus(fromRest);
    }

    /**
     * The ball jams the flipper: no velocity within {@link Arena#MAX_SPEED} leaves both it and what the ball is
     * squeezed against (a {@link Squeeze}). The flipper stops where it is, a stall, as a real flipper's motor does;
     * the ball stops where the flipper met it and keeps everything it touches, the flipper too, as contacts. The
     * flipper goes on once no ball touches it, or when it is sent the other way.
     */
    private void stall(Ball ball, Flipper flipper) {
        flipper.block();
        contacts.touchAll(ball);
        ball.setVelocity(Vect.ZERO);
        sceneChanged();
    }

    /**
     * Another ball. Balls that meet more slowly than two ticks of gravity, one of them lying on something (asleep, or
     * in persistent contact), are pressed together in a pile, not bouncing: each that meets a supported ball stops
     * closing on it and keeps it as a contact, as it would on a floor, and a floor feels nothing. So piles build
     * from the bottom and settle. Otherwise the two bounce elastically, and a sleeping one wakes.
     */
    private Struck hitBall(Ball ball, Ball other) {
        Vect normal = ball.position().minus(other.position()).unitSize();
        double approach = -ball.velocity().minus(detector.motion(other)).dot(normal);
        boolean slow = approach <= Math.max(Tolerances.ROUNDING_SPEED, REST_TICKS_OF_GRAVITY * Math.abs(gravity) * dt);
        if (slow && (Contacts.supports(other, ball) || Contacts.supports(ball, other))) {
            restAgainst(ball, other);
            restAgainst(other, ball);
            if (-ball.velocity().minus(other.velocity()).dot(normal) > Tolerances.ROUNDING_SPEED) {
                pressTogether(ball, other, normal);
            }
            restingContact = true;
            return new Struck.OtherBall(other.name());
        }
        actions.recordEvent(new PlayEvent.Hit(new Struck.OtherBall(other.name()), null, approach, ball.name(),
                ball.position()));
        other.setStillTicks(0);
        if (other.isAsleep()) {
            view.sleepers().wake(other);
            findAwake();
            schedule.forgetAll();
        }
        Geometry.VectPair after = Geometry.reflectBalls(ball.position(), 1, ball.velocity(), other.position(), 1,
                other.velocity());
        ball.setVelocity(after.v1);
        other.setVelocity(after.v2);
        energy.bounced(ball, normal, true);
        energy.bounced(other, normal.neg(), true);
        energy.met(ball, other);
        return new Struck.OtherBall(other.name());
    }

    /**
     * The support itself moves into the ball: they go on together along the normal, momentum kept, and neither
     * presses into what else holds it (the support's floor takes what the support cannot). Each of those steps may
     * undo a little of the other, so they repeat until the pair closes no faster than rounding: the fixed point
     * the loop would otherwise reach only through a chain of zero-time collisions, one step each.
     */
    private void pressTogether(Ball ball, Ball other, Vect normal) {
        List<Vect> holdingBall = contacts.normalsBesides(ball, new ContactRef.OnBall(other.name()));
        List<Vect> holdingOther = contacts.normalsBesides(other, new ContactRef.OnBall(ball.name()));
        for (int step = 0; step < PRESS_STEPS
                && -ball.velocity().minus(other.velocity()).dot(normal) > Tolerances.ROUNDING_SPEED; step++) {
            double common = (ball.velocity().dot(normal) + other.velocity().dot(normal)) / 2;
            ball.setVelocity(Contacts.project(ball.velocity().plus(normal.times(common - ball.velocity().dot(normal))),
                    holdingBall));
            other.setVelocity(Contacts.project(
                    other.velocity().plus(normal.times(common - other.velocity().dot(normal))), holdingOther));
        }
        energy.lost(ball);
        energy.lost(other);
    }

    /** The ball, awake, stops closing on a supporting ball and keeps it as a contact. */
    private void restAgainst(Ball ball, Ball support) {
        if (!ball.isAsleep() && Contacts.supports(support, ball)) {
            comeToRest(ball, new ContactRef.OnBall(support.name()));
        }
    }

    private void noteCollision(Collision collision) {
        lastCollisionAt.put(collision.ball(), elapsed);
        if (collision.contact() instanceof Contact.OtherBall other) {
            lastCollisionAt.put(other.other(), elapsed);
        }
    }

    /** A ball over its own collision cap moves no more in this tick: the guard acts on it alone. */
    private void capBall(Ball ball) {
        if (collisionsOf.merge(ball, 1, Integer::sum) == MAX_COLLISIONS_OF_A_BALL) {
            capped++;
            finished.add(ball);
            energy.lost(ball);
            schedule.forget(ball);
            schedule.sped(ball);
        }
    }

    /**
     * The cluster of touching contacts a collision must be solved with at once, or null when the collision is a
     * contact of its own (docs/design.md, "Contact clusters"). A collision at the very moment of a ball's last one is a
     * chain through touching contacts; one simultaneous solve ends it, where one contact at a time would go on at no
     * time apart. A ball that has collided {@link #RATTLE_COLLISIONS} times in the tick and again within
     * {@link #RATTLE_TIME} is rattling between surfaces it nearly touches (a ball in the apex of a narrow pocket,
     * without gravity to settle it): the surfaces within twice the way it went since count as touching it, so one
     * solve ends the rattle as well.
     */
    private ContactCluster clusterToSolve(Collision collision) {
        Contact contact = collision.contact();
        if (view.loopMode() != LoopMode.CONTINUOUS || contact instanceof Contact.Face face
                && face.gizmo() instanceof Absorber) {
            return null;
        }
        Ball ball = collision.ball();
        Ball other = contact instanceof Contact.OtherBall on ? on.other() : null;
        double reach;
        if (again(ball) || other != null && again(other)) {
            reach = ContactCluster.TOUCHING;
        } else if (rattling(ball)) {
            reach = Math.min(RATTLE_REACH, 2 * ball.velocity().length() * (elapsed - lastCollisionAt.get(ball)));
        } else {
            return null;
        }
        return ContactCluster.around(view, other == null ? List.of(ball) : List.of(ball, other), detector::motion,
                candidate -> !finished.contains(candidate), reach);
    }

    private boolean rattling(Ball ball) {
        Double last = lastCollisionAt.get(ball);
        return last != null && elapsed - last <= RATTLE_TIME
                && collisionsOf.getOrDefault(ball, 0) >= RATTLE_COLLISIONS;
    }

    private boolean again(Ball ball) {
        Double last = lastCollisionAt.get(ball);
        return last != null && elapsed - last <= ZERO_TIME;
    }

    /**
     * Solves the cluster's normal impulses at once ({@link NormalImpulses}): no contact is left closing, each impact
     * bounces with its coefficient where the contacts allow it, swinging flippers give velocity and take none. Where
     * no velocity within {@link Arena#MAX_SPEED} leaves the swinging parts, they stall (a jam) and the cluster is
     * solved again with them still. Every impact is a hit that triggers; a slow one is resting contact.
     */
    private Struck resolveCluster(Collision collision, ContactCluster cluster) {
        List<Ball> balls = cluster.balls();
        NormalImpulses.Result result = solve(cluster, Set.of());
        Set<Flipper> stalled = new LinkedHashSet<>();
        if (!result.feasible()) {
            for (ContactCluster.Row row : cluster.rows()) {
                if (row.other() instanceof ContactCluster.Other.Swinging swinging
                        && stalled.add(swinging.flipper())) {
                    swinging.flipper().block();
                    actions.recordEvent(new PlayEvent.Jammed(swinging.flipper().name(), balls.get(row.ball()).name()));
                }
            }
            result = solve(cluster, stalled);
        }
        boolean woke = false;
        for (int k = 0; k < balls.size(); k++) {
            Ball ball = balls.get(k);
            Vect after = new Vect(result.vx()[k], result.vy()[k]);
            if (after.equals(detector.motion(ball))) {
                continue;
            }
            if (ball.isAsleep()) {
                view.sleepers().wake(ball);
                woke = true;
            }
            ball.setVelocity(after);
            ball.setStillTicks(0);
            energy.lost(ball);
            schedule.forget(ball);
            schedule.sped(ball);
        }
        Struck hit = noteImpacts(collision, cluster, result);
        if (woke || !stalled.isEmpty()) {
            sceneChanged();
        }
        return hit;
    }

    private NormalImpulses.Result solve(ContactCluster cluster, Set<Flipper> stalled) {
        List<ContactCluster.Row> rows = cluster.rows();
        int n = rows.size();
        int[] a = new int[n];
        int[] b = new int[n];
        double[] nx = new double[n];
        double[] ny = new double[n];
        double[] speed = new double[n];
        double[] restitution = new double[n];
        double[] impact = impactSpeeds(cluster);
        for (int i = 0; i < n; i++) {
            ContactCluster.Row row = rows.get(i);
            a[i] = row.ball();
            b[i] = row.other() instanceof ContactCluster.Other.InCluster in ? in.index() : -1;
            nx[i] = row.normal().x();
            ny[i] = row.normal().y();
            boolean still = row.other() instanceof ContactCluster.Other.Swinging s && stalled.contains(s.flipper());
            speed[i] = still ? 0 : row.surfaceSpeed();
            restitution[i] = row.restitution();
        }
        List<Ball> balls = cluster.balls();
        double[] vx = new double[balls.size()];
        double[] vy = new double[balls.size()];
        for (int k = 0; k < balls.size(); k++) {
            Vect v = detector.motion(balls.get(k));
            vx[k] = v.x();
            vy[k] = v.y();
        }
        return new NormalImpulses(balls.size(), a, b, nx, ny, speed, restitution).solve(vx, vy, impact,
                Arena.MAX_SPEED);
    }

    /**
     * The closing speed above which a contact of a cluster is an impact that bounces, as for a single contact (see
     * {@link #restingSpeed}): two ticks of the gravity pressing the ball into a surface as the ball's other contacts
     * in the cluster leave it, so a ball set on a floor settles, one pressed into a surface above or beside it by
     * no gravity bounces; between balls, two ticks of gravity, as for two balls alone ({@link #hitBall}).
     */
    private double[] impactSpeeds(ContactCluster cluster) {
        List<ContactCluster.Row> rows = cluster.rows();
        double[] impact = new double[rows.size()];
        for (int i = 0; i < rows.size(); i++) {
            ContactCluster.Row row = rows.get(i);
            double pressing;
            if (row.other() instanceof ContactCluster.Other.Still
                    || row.other() instanceof ContactCluster.Other.Swinging) {
                List<Vect> others = new ArrayList<>();
                for (int j = 0; j < rows.size(); j++) {
                    if (j != i && rows.get(j).ball() == row.ball()) {
                        others.add(rows.get(j).normal());
                    }
                }
                pressing = Math.max(0, -Contacts.project(new Vect(0, gravity), others).dot(row.normal()));
            } else {
                pressing = Math.abs(gravity);
            }
            impact[i] = Math.max(Tolerances.ROUNDING_SPEED, REST_TICKS_OF_GRAVITY * pressing * dt);
        }
        return impact;
    }

    /**
     * The hits of a solved cluster (each contact whose impulse was an impact, once per surface) for the sound, the
     * flashes and stage 5; its resting contacts become persistent contacts. Returns what the collision itself hit.
     */
    private Struck noteImpacts(Collision collision, ContactCluster cluster, NormalImpulses.Result result) {
        Struck own = collision.contact().struck();
        Set<Struck> heard = new LinkedHashSet<>();
        List<Ball> balls = cluster.balls();
        double[] impact = impactSpeeds(cluster);
        for (int i = 0; i < cluster.rows().size(); i++) {
            ContactCluster.Row row = cluster.rows().get(i);
            Ball ball = balls.get(row.ball());
            double change = result.compression()[i];
            if (change <= 0) {
                continue;
            }
            if (change <= impact[i]) {
                rest(ball, row, balls);
                continue;
            }
            Struck struck = struckBy(row, balls);
            if (struck instanceof TriggerSource.OfGizmo gizmo) {
                GizmoBase target = view.gizmo(gizmo.gizmo());
                if (target != null) {
                    target.markTriggered(now());
                }
            }
            if (heard.add(struck)) {
                actions.recordEvent(new PlayEvent.Hit(struck, kindOf(struck), change, ball.name(), ball.position()));
                if (struck instanceof TriggerSource source && !struck.equals(own)) {
                    alsoHit.add(source);
                }
            }
        }
        return own;
    }

    private void rest(Ball ball, ContactCluster.Row row, List<Ball> balls) {
        if (row.other() instanceof ContactCluster.Other.Still still) {
            Contacts.attach(ball, still.ref());
        } else if (row.other() instanceof ContactCluster.Other.InCluster in) {
            Ball other = balls.get(in.index());
            restAgainst(ball, other);
            restAgainst(other, ball);
        }
    }

    private Struck struckBy(ContactCluster.Row row, List<Ball> balls) {
        if (row.other() instanceof ContactCluster.Other.Still still) {
            return still.gizmo() == null ? TriggerSource.OUTER_WALLS : TriggerSource.gizmo(still.gizmo().name());
        }
        if (row.other() instanceof ContactCluster.Other.Swinging swinging) {
            return TriggerSource.gizmo(swinging.flipper().name());
        }
        if (row.other() instanceof ContactCluster.Other.InCluster in) {
            return new Struck.OtherBall(balls.get(in.index()).name());
        }
        return new Struck.OtherBall(((ContactCluster.Other.Beyond) row.other()).ball().name());
    }

    private GizmoKind kindOf(Struck struck) {
        if (struck instanceof TriggerSource.OfGizmo gizmo) {
            GizmoBase target = view.gizmo(gizmo.gizmo());
            return target == null ? null : target.kind();
        }
        return null;
    }

    /** Stage 5: the gizmo or the walls that were hit trigger every gizmo connected to them. */
    private void stage5Triggering(TriggerSource source) {
        double now = now();
        for (Connection connection : view.connections()) {
            if (connection.source().equals(source)) {
                GizmoBase target = view.gizmo(connection.target());
                if (target != null) {
                    actions.trigger(target, now);
                    sceneChanged();   // a flipper turned round, an absorber fired, balls woke
                }
            }
        }
    }

    /** Stage 6: the report of this tick; the board hands it to the observers. */
    private TickReport report() {
        int asleep = 0;
        List<BallReport> balls = new ArrayList<>();
        double lookAhead = view.nextCollisionLookAhead();
        for (Ball ball : view.balls()) {
            if (ball.isCaptured()) {
                continue;
            }
            asleep += ball.isAsleep() ? 1 : 0;
            if (lookAhead > 0) {
                balls.add(ballReport(ball, lookAhead));
            }
        }
        nanos.put(Stage.REDRAWING, view.lastRedrawNanos());
        return new TickReport(view.time(), nanos, collisions, zeroTimeCollisions, awake.size(), asleep,
                new GuardCounts(wedged, pinched, capped), actions.drainEvents(), balls);
    }

    private BallReport ballReport(Ball ball, double lookAhead) {
        BallReport.BallState state = ball.isAsleep() ? BallReport.BallState.ASLEEP
                : ball.contacts().isEmpty() ? BallReport.BallState.FLYING : BallReport.BallState.CONTACT;
        double in = Double.POSITIVE_INFINITY;
        Vect at = null;
        if (!ball.isAsleep()) {
            Earliest earliest = detector.againstScene(ball, lookAhead);
            for (Ball other : view.balls()) {
                if (other != ball && !other.isCaptured()) {
                    detector.againstBall(ball, other, lookAhead, earliest);
                }
            }
            if (earliest.collision() != null) {
                in = earliest.collision().time();
                at = ball.position().plus(ball.velocity().times(in));
            }
        }
        return new BallReport(ball.name(), ball.position(), ball.velocity(), state, in, at);
    }

    private long lap(Stage stage, long since) {
        long now = System.nanoTime();
        nanos.merge(stage, now - since, Long::sum);
        return now;
    }

    /** A trigger, a capture or a held flipper changed the scene: which balls move, and what they can hit. */
    private void sceneChanged() {
        findAwake();
        schedule.file(freeBalls(), elapsed);   // filing forgets every known collision
    }

    private void findAwake() {
        schedule.awakeChanged();
        awake.clear();
        for (Ball ball : view.balls()) {
            if (!ball.isCaptured() && !ball.isAsleep()) {
                awake.add(ball);
            }
        }
    }

    private List<Ball> freeBalls() {
        List<Ball> free = new ArrayList<>();
        for (Ball ball : view.balls()) {
            if (!ball.isCaptured()) {
                free.add(ball);
            }
        }
        return free;
    }

    /** The balls of a resolved collision move differently now: stage 3 asks about them again. */
    private void forgetWhatChanged(Collision collision) {
        schedule.forget(collision.ball());
        schedule.sped(collision.ball());
        if (collision.contact() instanceof Contact.OtherBall other) {
            schedule.forget(other.other());
            schedule.sped(other.other());
        }
    }

    /**
     * SEED: whether the collision ends its balls' motion for the tick. A resting contact only projects the velocity:
     * no bounce to stop at; a ball a swinging flipper struck is carried on for the rest of the tick, or the flipper
     * would swing into it where it stopped. Nor is a collision at the very
     * start of the ball's motion: balls that stopped where they touch would meet there again every tick, never
     * moving apart, while gravity pumped their velocities up.
     */
    private boolean finishes(Collision collision) {
        return !restingContact && !carried.contains(collision.ball()) && elapsed > ZERO_TIME;
    }

    /** SEED: the ball (and a ball it hit) stays put for the rest of the tick. */
    private void finish(Collision collision) {
        finished.add(collision.ball());
        if (collision.contact() instanceof Contact.OtherBall other) {
            finished.add(other.other());
        }
    }

    private double now() {
        return startTime + elapsed;
    }
}
