package gizmoball.model;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.DoubleFunction;

import physics.Circle;
import physics.Geometry;
import physics.LineSegment;
import physics.Vect;

/**
 * One tick of the six-stage loop of SPEC.md on a board. Stage 1 changes the velocities; then stages 3 (detect,
 * through a {@link CollisionSchedule} that asks again only about what the last collision changed), 2 (move
 * everything to the collision), 4 (resolve) and 5 (trigger) repeat until the tick is used up; stage 6 notifies
 * the observers. In {@link LoopMode#SEED} a ball that has bounced stays where it is for the rest of the
 * tick (the classic loop: one move, at most one collision per ball and tick; per ball, because one ball lying on
 * the floor would otherwise stop every ball on the board); in {@link LoopMode#CONTINUOUS} it goes on moving, so
 * no time is lost.
 *
 * <p>Resting contact (pitfall 11): a ball meeting a fixed surface more slowly than about two ticks of gravity
 * loses its normal velocity instead of bouncing, so a ball lying on a surface sees one zero-time collision per
 * tick, keeps its position and ends the tick at rest on it. Guards bound the work of a tick: a touch whose
 * zero-time collision changed no velocity (it closes at a rounding of the velocity) is settled and not met again
 * at zero time until its balls' velocities change; a ball with many zero-time collisions in one tick is wedged
 * and stops (also against a flipper held still); a flipper hitting the same ball again and again in one
 * tick is pinching it against something and is held still for the rest of the tick; a tick with an absurd number
 * of collisions ends early (nothing moves any further, so nothing overlaps).
 *
 * <p>Energy: in free flight the integration (gravity, then a straight move) keeps the shadow energy
 * |v - g dt/2 y|^2/2 - g y exactly, but an elastic bounce part-way through a tick moves it by up to g dt |v|
 * either way, and many such bounces would random-walk the energy. So in CONTINUOUS mode a ball whose collisions
 * in a tick were all elastic gets its speed rescaled at the end of the tick to keep its shadow energy; energy()
 * of a lone ball then stays within g dt |v| of its start for ever.
 */
final class TickRun {
    /** A collision sooner than this after the previous one counts as zero-time. */
    static final double ZERO_TIME = 1e-12;
    private static final int ZERO_TIME_HITS_BEFORE_WEDGED = 8;
    private static final int FLIPPER_HITS_BEFORE_PINCHED = 3;
    private static final int MAX_COLLISIONS_BASE = 500;
    private static final int MAX_COLLISIONS_PER_BALL = 100;
    /** Slower normal approach than this many ticks' worth of gravity is resting contact. */
    private static final double REST_TICKS_OF_GRAVITY = 2;
    /** A larger correction than this would not be a rounding of the bounce timing: leave the ball alone. */
    private static final double MAX_SHADOW_RESCALE = 0.5;
    /** Floor of the resting speed, for a board without gravity: rounding, not motion. */
    private static final double MIN_REST_SPEED = 1e-9;

    private final Board board;
    private final double dt;
    private final double startTime;
    private final double restSpeed;
    private final Set<Flipper> stoppedFlippers = new HashSet<>();
    private final CollisionDetector detector;
    private final CollisionSchedule schedule;
    private final Set<CollisionDetector.Touch> settled = new HashSet<>();
    private final Map<Ball, Integer> zeroTimeHits = new HashMap<>();
    private final Map<List<Object>, Integer> flipperHits = new HashMap<>();
    /** SEED: balls that have had their collision this tick and move no more. */
    private final Set<Ball> finished = new HashSet<>();
    private final Map<Ball, Double> shadowAtStart = new HashMap<>();
    /** In order of first bounce (insertion order keeps every run bit-for-bit the same). */
    private final Set<Ball> bouncedElastically = new LinkedHashSet<>();
    private final Set<Ball> lostEnergy = new HashSet<>();
    private final List<List<Ball>> ballPairs = new ArrayList<>();
    private double elapsed;
    /** Whether the collision stage 4 resolved last was a resting contact rather than a bounce. */
    private boolean restingContact;

    TickRun(Board board, double dt) {
        this.board = board;
        this.dt = dt;
        this.startTime = board.time();
        this.restSpeed = Math.max(MIN_REST_SPEED, REST_TICKS_OF_GRAVITY * Math.abs(board.gravity()) * dt);
        this.detector = new CollisionDetector(board, stoppedFlippers, finished, settled);
        this.schedule = new CollisionSchedule(detector);
    }

    void run() {
        stage1FrictionAndGravity();
        double remaining = dt;
        int collisions = 0;
        int maxCollisions = MAX_COLLISIONS_BASE + MAX_COLLISIONS_PER_BALL * board.ballStates().size();
        while (remaining > 0) {
            Collision collision = stage3CollisionDetection(remaining);
            if (collision == null) {
                stage2BallMotion(remaining);
                break;
            }
            stage2BallMotion(collision.time());
            remaining -= collision.time();
            List<Ball> involved = ballsOf(collision);
            List<Vect> before = velocitiesOf(involved);
            String hit = stage4CollisionResolution(collision);
            settleOrUnsettle(collision, involved, before);
            forgetWhatChanged(collision);
            if (hit != null) {
                stage5Triggering(hit);
            }
            if (board.loopMode() == LoopMode.SEED && !restingContact) {
                finish(collision);   // a resting contact only projects the velocity: it is no bounce to stop at
            }
            if (++collisions >= maxCollisions) {
                break;
            }
        }
        if (board.loopMode() == LoopMode.CONTINUOUS) {
            keepShadowEnergyOfElasticBounces();   // SEED stays the classic loop, lost time and all
        }
        board.advanceTime(dt);
        stage6Notify();
    }

    /** Stage 1: V_new = V_old * (1 - mu*dt - mu2*|V_old|*dt), then gravity; speed clamped to MAX_SPEED. */
    private void stage1FrictionAndGravity() {
        for (Ball ball : freeBalls()) {
            Vect v = ball.velocity();
            double factor = Math.max(0, 1 - board.mu() * dt - board.mu2() * v.length() * dt);
            Vect next = v.times(factor).plus(new Vect(0, board.gravity() * dt));
            ball.setVelocity(next);
            if (ball.velocity().equals(next)) {
                shadowAtStart.put(ball, shadowEnergyAfterStage1(ball));
            }
        }
    }

    /** Stage 2: balls move in straight lines, swinging flippers turn (stopping at their limits), for time t. */
    private void stage2BallMotion(double t) {
        for (Ball ball : freeBalls()) {
            if (!finished.contains(ball)) {
                ball.advance(t);
            }
        }
        for (GizmoBase gizmo : board.gizmoBases()) {
            if (gizmo instanceof Flipper flipper && !stoppedFlippers.contains(flipper)) {
                flipper.advance(t);
            }
        }
        elapsed += t;
    }

    /** Stage 3: the earliest collision within the time left, or null. */
    private Collision stage3CollisionDetection(double window) {
        return schedule.next(freeBalls(), elapsed, window);
    }

    /**
     * Stage 4: the ball and what it hits touch now; reflect with the matching physics-lib method (or capture).
     * Returns the name of the trigger source that was hit (a gizmo or the outer walls), null for a ball.
     */
    private String stage4CollisionResolution(Collision collision) {
        Ball ball = collision.ball();
        boolean zeroTime = collision.time() <= ZERO_TIME;
        Contact contact = collision.contact();
        restingContact = false;
        String hit;
        if (contact instanceof Contact.Wall wall) {
            hit = hitFixed(ball, wall.gizmo(), coeff -> Geometry.reflectWall(wall.segment(), ball.velocity(), coeff));
        } else if (contact instanceof Contact.Round round) {
            hit = hitFixed(ball, round.gizmo(),
                    coeff -> Geometry.reflectCircle(round.circle().getCenter(), ball.position(), ball.velocity(), coeff));
        } else if (contact instanceof Contact.FlipperPart part) {
            hit = hitFlipper(ball, part);
        } else {
            hit = hitBall(ball, ((Contact.OtherBall) contact).other());
        }
        if (zeroTime && countZeroTimeHit(ball) && !isSwingingFlipper(collision.contact())) {
            ball.setVelocity(Vect.ZERO);   // wedged between surfaces: at rest for this tick
            lostEnergy.add(ball);
        }
        return hit;
    }

    /** Stage 5: the gizmo or the walls that were hit trigger every gizmo connected to them. */
    private void stage5Triggering(String source) {
        double now = now();
        for (Connection connection : board.connections()) {
            if (connection.source().equals(source)) {
                GizmoBase target = board.gizmoBase(connection.target());
                if (target != null) {
                    board.performAction(target, now);
                    sceneChanged();   // a flipper turned round or an absorber fired
                }
            }
        }
    }

    /** Stage 6: observers redraw. */
    private void stage6Notify() {
        board.notifyObservers(BoardChange.TICK);
    }

    private String hitFixed(Ball ball, GizmoBase gizmo, DoubleFunction<Vect> reflect) {
        if (gizmo instanceof Absorber absorber) {
            absorber.markTriggered(now());
            board.capture(ball, absorber);
            lostEnergy.add(ball);
            return absorber.name();
        }
        double coefficient = gizmo == null ? 1.0 : gizmo.reflectionCoefficient();
        boolean rested = reflectOrRest(ball, reflect, coefficient);
        (rested || coefficient != 1.0 ? lostEnergy : bouncedElastically).add(ball);
        if (gizmo == null) {
            return Board.OUTER_WALLS;
        }
        gizmo.markTriggered(now());
        return gizmo.name();
    }

    /**
     * Reflects with the coefficient, unless the ball approaches so slowly that this is resting contact: then only
     * the normal part of its velocity goes (coefficient 0) and it stays on the surface.
     */
    private boolean reflectOrRest(Ball ball, DoubleFunction<Vect> reflect, double coefficient) {
        Vect before = ball.velocity();
        boolean resting = reflect.apply(1.0).minus(before).length() / 2 <= restSpeed;
        ball.setVelocity(reflect.apply(resting ? 0.0 : coefficient));
        restingContact = resting;
        return resting;
    }

    private String hitFlipper(Ball ball, Contact.FlipperPart part) {
        Flipper flipper = part.flipper();
        flipper.markTriggered(now());
        lostEnergy.add(ball);
        Shape shape = flipper.shape();
        if (!detector.isMoving(flipper)) {
            if (part.circle()) {
                Vect centre = shape.circles().get(part.index()).getCenter();
                reflectOrRest(ball, coeff -> Geometry.reflectCircle(centre, ball.position(), ball.velocity(), coeff),
                        Flipper.REFLECTION);
            } else {
                LineSegment side = shape.segments().get(part.index());
                reflectOrRest(ball, coeff -> Geometry.reflectWall(side, ball.velocity(), coeff), Flipper.REFLECTION);
            }
            return flipper.name();
        }
        double omega = flipper.angularVelocity();
        Vect pivot = flipper.pivot();
        Circle circle = ball.circle();
        if (part.circle()) {
            ball.setVelocity(Geometry.reflectRotatingCircle(shape.circles().get(part.index()), pivot, omega, circle,
                    ball.velocity(), Flipper.REFLECTION));
        } else {
            try {
                ball.setVelocity(Geometry.reflectRotatingWall(shape.segments().get(part.index()), pivot, omega, circle,
                        ball.velocity(), Flipper.REFLECTION));
            } catch (IllegalArgumentException atSegmentEnd) {
                // The contact is at the end of the side, which lies on an end circle: resolve it there (pitfall 9).
                Circle end = nearestEnd(shape, ball.position());
                ball.setVelocity(Geometry.reflectRotatingCircle(end, pivot, omega, circle, ball.velocity(),
                        Flipper.REFLECTION));
            }
        }
        if (countFlipperHit(ball, flipper)) {
            stoppedFlippers.add(flipper);   // the ball is pinched: hold the flipper rather than push it through
            sceneChanged();
        }
        return flipper.name();
    }

    private static Circle nearestEnd(Shape shape, Vect point) {
        Circle pivotEnd = shape.circles().get(Flipper.PIVOT_CIRCLE);
        Circle tipEnd = shape.circles().get(Flipper.TIP_CIRCLE);
        return pivotEnd.getCenter().distanceSquared(point) <= tipEnd.getCenter().distanceSquared(point)
                ? pivotEnd : tipEnd;
    }

    private String hitBall(Ball ball, Ball other) {
        Geometry.VectPair after = Geometry.reflectBalls(ball.position(), 1, ball.velocity(), other.position(), 1,
                other.velocity());
        ball.setVelocity(after.v1);
        other.setVelocity(after.v2);
        bouncedElastically.add(ball);
        bouncedElastically.add(other);
        ballPairs.add(List.of(ball, other));
        return null;
    }

    private void sceneChanged() {
        schedule.forgetAll();
        settled.clear();
    }

    private static List<Ball> ballsOf(Collision collision) {
        return collision.contact() instanceof Contact.OtherBall other ? List.of(collision.ball(), other.other())
                : List.of(collision.ball());
    }

    private static List<Vect> velocitiesOf(List<Ball> balls) {
        return balls.stream().map(Ball::velocity).toList();
    }

    /**
     * A zero-time collision whose resolution left every velocity as it was closes at a rounding of the velocity
     * (the reflection's change fell below the last digit): detection would report it again at once, for ever,
     * with no time passing. It is settled: the detector skips its zero-time collisions until a velocity of its
     * balls changes. A swinging flipper is never settled, it turns on into the ball (the pinch guard bounds it).
     */
    private void settleOrUnsettle(Collision collision, List<Ball> involved, List<Vect> before) {
        if (!velocitiesOf(involved).equals(before)) {
            settled.removeIf(touch -> involved.contains(touch.ball())
                    || touch.contact() instanceof Contact.OtherBall other && involved.contains(other.other()));
        } else if (collision.time() <= ZERO_TIME && !isSwingingFlipper(collision.contact())) {
            settled.add(new CollisionDetector.Touch(collision.ball(), collision.contact()));
            if (collision.contact() instanceof Contact.OtherBall other) {
                settled.add(new CollisionDetector.Touch(other.other(), new Contact.OtherBall(collision.ball())));
            }
        }
    }

    /** The balls of a resolved collision move differently now: stage 3 asks about them again. */
    private void forgetWhatChanged(Collision collision) {
        schedule.forget(collision.ball());
        if (collision.contact() instanceof Contact.OtherBall other) {
            schedule.forget(other.other());
        }
    }

    /** SEED: the ball (and a ball it hit) stays put for the rest of the tick. */
    private void finish(Collision collision) {
        finished.add(collision.ball());
        if (collision.contact() instanceof Contact.OtherBall other) {
            finished.add(other.other());
        }
    }

    /**
     * The shadow energy the integration keeps in free flight, |u|^2/2 - g y with u the velocity half a gravity
     * kick back: right after stage 1 that is v - g dt/2 y; at the end of a tick it is v + g dt/2 y.
     */
    private double shadowEnergyAfterStage1(Ball ball) {
        Vect u = ball.velocity().minus(new Vect(0, board.gravity() * dt / 2));
        return u.dot(u) / 2 - board.gravity() * ball.position().y();
    }

    /**
     * Rescales the velocities of the balls whose collisions this tick were all elastic (with fixed shapes of
     * coefficient 1 or with each other; a ball that met a lossy one counts as lossy too) so that their shadow
     * energy is what it was at the start. Ball-ball collisions conserve a group's total, not each ball's, so the
     * balls that met each other share one factor s: with h = g dt/2 and n balls in the group, s solves
     * s^2 sum|v|^2 + 2 s h sum(v_y) + n h^2 = 2 (sum S + g sum y).
     */
    private void keepShadowEnergyOfElasticBounces() {
        Map<Ball, List<Ball>> groups = new LinkedHashMap<>();
        for (Ball ball : bouncedElastically) {
            groups.put(ball, new ArrayList<>(List.of(ball)));
        }
        for (List<Ball> pair : ballPairs) {
            List<Ball> first = groups.get(pair.get(0));
            List<Ball> second = groups.get(pair.get(1));
            if (first != second) {
                first.addAll(second);
                second.forEach(ball -> groups.put(ball, first));
            }
        }
        new LinkedHashSet<>(groups.values()).forEach(this::keepShadowEnergy);
    }

    private void keepShadowEnergy(List<Ball> group) {
        for (Ball ball : group) {
            if (lostEnergy.contains(ball) || ball.isCaptured() || !shadowAtStart.containsKey(ball)) {
                return;
            }
        }
        double g = board.gravity();
        double h = g * dt / 2;
        double speedsSquared = 0;
        double verticals = 0;
        double target = 0;
        for (Ball ball : group) {
            speedsSquared += ball.velocity().dot(ball.velocity());
            verticals += ball.velocity().y();
            target += 2 * (shadowAtStart.get(ball) + g * ball.position().y());
        }
        double discriminant = h * h * verticals * verticals - speedsSquared * (group.size() * h * h - target);
        if (speedsSquared == 0 || discriminant < 0) {
            return;
        }
        double scale = (-h * verticals + Math.sqrt(discriminant)) / speedsSquared;
        if (Math.abs(scale - 1) < MAX_SHADOW_RESCALE) {
            group.forEach(ball -> ball.setVelocity(ball.velocity().times(scale)));
        }
    }

    private boolean isSwingingFlipper(Contact contact) {
        return contact instanceof Contact.FlipperPart part && detector.isMoving(part.flipper());
    }

    /** Counts a zero-time collision of the ball; true once it has had too many this tick. */
    private boolean countZeroTimeHit(Ball ball) {
        return zeroTimeHits.merge(ball, 1, Integer::sum) > ZERO_TIME_HITS_BEFORE_WEDGED;
    }

    /** Counts a hit of the ball by the swinging flipper; true once it has been hit too often this tick. */
    private boolean countFlipperHit(Ball ball, Flipper flipper) {
        return flipperHits.merge(List.of(ball, flipper), 1, Integer::sum) >= FLIPPER_HITS_BEFORE_PINCHED;
    }

    private List<Ball> freeBalls() {
        List<Ball> free = new ArrayList<>();
        for (Ball ball : board.ballStates()) {
            if (!ball.isCaptured()) {
                free.add(ball);
            }
        }
        return free;
    }

    private double now() {
        return startTime + elapsed;
    }
}
