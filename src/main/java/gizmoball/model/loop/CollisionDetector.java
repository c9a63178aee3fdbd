package gizmoball.model.loop;

import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.MovingShape;
import gizmoball.model.gizmo.Shape;

import java.util.ArrayList;
import java.util.List;

import physics.Angle;
import physics.Circle;
import physics.Geometry;
import physics.GeometryImpl;
import physics.GeometryInterface;
import physics.LineSegment;
import physics.Vect;

/**
 * Stage 3 of the loop, for one ball: the time until it hits the outer walls, each gizmo shape it can reach, or
 * another ball. All times come from physics.Geometry, a pair of balls' as it gives it ({@link BallMeeting}). A moving
 * shape (a swinging flipper) is asked through the rotating methods of a GeometryImpl whose foresight ends when it stops
 * or the window does (the library's rotation goes on for ever; docs/design.md, "Rotation that stops"); after a stop it
 * is a fixed shape there.
 *
 * <p>A touch that does not close faster than {@link Tolerances#ROUNDING_SPEED} is a graze, not a collision: a
 * ball rolling along a surface, across a seam or past a corner it only brushes is never stopped for it
 * (docs/design.md, "Grazes").
 */
final class CollisionDetector {

    /** The outer walls as contacts, made once (a contact is a value: the same wall is the same contact). */
    private static final List<Contact.OuterWall> WALL_CONTACTS = List.of(
            new Contact.OuterWall(0, Arena.OUTER_WALLS.get(0)), new Contact.OuterWall(1, Arena.OUTER_WALLS.get(1)),
            new Contact.OuterWall(2, Arena.OUTER_WALLS.get(2)), new Contact.OuterWall(3, Arena.OUTER_WALLS.get(3)));

    private final LoopView view;
    private final FinishedBalls finishedBalls;
    /** The search of {@link #againstScene}, kept from ask to ask. */
    private final Earliest scene = new Earliest(0);
    /** The gizmos a ball can reach, found again for every ask. */
    private final List<GizmoBase> reached = new ArrayList<>();
    /** The box the asking ball sweeps in the window: what lies outside it is not asked about. */
    private final SweptBox swept = new SweptBox();

    /** {@link LoopSettings#rotatingSearchSlices()}. */
    private final int rotatingSearchSlices;
    /**
     * The last rotating search's physics-lib and the foresight it was made with: the balls asked in one search share
     * the time left, so one is made per foresight, not per ball and moving shape.
     */
    private GeometryInterface rotating;
    private double rotatingForesight = Double.NaN;

    /** @param finishedBalls balls that move no more this tick (SEED), treated as at rest */
    CollisionDetector(LoopView view, FinishedBalls finishedBalls, LoopSettings settings) {
        this.view = view;
        this.finishedBalls = finishedBalls;
        this.rotatingSearchSlices = settings.rotatingSearchSlices();
    }

    /** The velocity the ball moves with for the rest of the tick: none while asleep or finished. */
    Vect motion(Ball ball) {
        return resting(ball) ? Vect.ZERO : ball.velocity();
    }

    /** The x of the ball's {@link #motion}, without making a vector. */
    double motionX(Ball ball) {
        return resting(ball) ? 0 : ball.vx();
    }

    /** The y of the ball's {@link #motion}, without making a vector. */
    double motionY(Ball ball) {
        return resting(ball) ? 0 : ball.vy();
    }

    /**
     * The speed of the ball's {@link #motion}, for a reach, which carries {@link Tolerances#REACH_MARGIN}, far above the
     * rounding: a plain square root, several times cheaper than the overflow-safe hypot behind {@link Vect#length()}.
     */
    double speedOf(Ball ball) {
        return resting(ball) ? 0 : Math.sqrt(ball.vx() * ball.vx() + ball.vy() * ball.vy());
    }

    /** Whether no ball has finished in this tick: then a filed ball's slot moves as the ball does ({@link Motions}). */
    boolean noneFinished() {
        return finishedBalls.isEmpty();
    }

    /** Whether the ball moves no more in this tick: asleep, or finished. */
    private boolean resting(Ball ball) {
        return ball.isAsleep() || finishedBalls.contains(ball);
    }

    /**
     * The ball's earliest collision with the outer walls or a gizmo within the window: a search the detector keeps, so
     * read it before asking again.
     */
    Earliest againstScene(Ball ball, double window) {
        Earliest earliest = scene;
        earliest.reset(window);
        double vx = motionX(ball);
        double vy = motionY(ball);
        boolean still = vx == 0 && vy == 0;
        swept.set(ball.x(), ball.y(), vx, vy, window);
        if (!still) {
            for (int side = 0; side < Arena.OUTER_WALLS.size(); side++) {
                LineSegment wall = Arena.OUTER_WALLS.get(side);
                if (swept.misses(wall) || !Approach.mayMeetLine(wall, ball.x(), ball.y(), vx, vy, earliest.limit())) {
                    continue;
                }
                double time = Geometry.timeUntilWallCollision(wall, circleAfter(ball, vx, vy, 0), new Vect(vx, vy));
                if (time <= earliest.limit() && closesOnSegment(wall, ball, vx, vy, time)) {
                    earliest.offer(time, ball, WALL_CONTACTS.get(side), false);
                }
            }
        }
        List<GizmoBase> reachable = reachable();
        for (int i = 0; i < reachable.size(); i++) {
            GizmoBase gizmo = reachable.get(i);
            if (gizmo instanceof MovingShape moving && moving.isMoving()) {
                againstMovingShape(ball, gizmo, moving, window, earliest);
            } else if (!still) {
                againstStillShape(ball, 0, gizmo, gizmo.shape(), earliest);
            }
        }
        return earliest;
    }

    /** The two balls' collision, if it comes within the window, offered to {@code earliest} as {@code ball}'s. */
    void againstBall(Ball ball, Ball other, double window, Earliest earliest) {
        // motion(ball) and motion(other) as their Vects hold them (a ball's velocity is kept so), and the centres'
        // offset and the relative motion on the components, without making a vector
        double mineX = motionX(ball);
        double mineY = motionY(ball);
        double theirsX = motionX(other);
        double theirsY = motionY(other);
        double rx = mineX - theirsX;
        double ry = mineY - theirsY;
        double dx = ball.x() - other.x();
        double dy = ball.y() - other.y();
        if (!Approach.mayMeetBall(dx, dy, rx, ry, window)) {
            return;   // too far for their speed, not closing (the API's own first answer is then "never"), or passing
        }
        if (view.passingThrough(ball, other)) {
            return;   // placed on each other (a loaded file may do that): they pass through until they are apart
        }
        double time = BallMeeting.time(dx, dy, rx, ry);   // Geometry.timeUntilBallBallCollision's
        if (time <= window) {
            // ball.position().plus(mine.times(time)).minus(other.position().plus(theirs.times(time))) and
            // mine.minus(theirs), on the components with Vect's + 0.0 at each made vector (the same doubles)
            double awayX = at(ball.x(), mineX, time) - at(other.x(), theirsX, time) + 0.0;
            double awayY = at(ball.y(), mineY, time) - at(other.y(), theirsY, time) + 0.0;
            if (closingOnCircle(awayX, awayY, rx + 0.0, ry + 0.0)) {
                earliest.offer(time, ball, other.asContact(), true);
            }
        }
    }

    /** The gizmos whose cells meet the box the asking ball sweeps (all gizmos without the index). */
    private List<GizmoBase> reachable() {
        if (!view.spatialIndexEnabled()) {
            reached.clear();
            reached.addAll(view.gizmos());
            return reached;
        }
        view.index().within(swept.minX, swept.minY, swept.maxX, swept.maxY, reached);
        return reached;
    }

    /**
     * A shape that does not move, met by the moving ball from where it will be after {@code delay} seconds, still
     * within the box it sweeps in the window, so what lies outside the box is passed over.
     */
    private void againstStillShape(Ball ball, double delay, GizmoBase gizmo, Shape shape, Earliest earliest) {
        // Where the ball is after the delay, and how it moves, for the tests that pass over what it cannot meet
        double vx = motionX(ball);
        double vy = motionY(ball);
        double cx = ball.x() + vx * delay;
        double cy = ball.y() + vy * delay;
        List<LineSegment> segments = shape.segments();
        for (int i = 0; i < segments.size(); i++) {
            if (swept.misses(segments.get(i))
                    || !Approach.mayMeetLine(segments.get(i), cx, cy, vx, vy, earliest.limit() - delay)) {
                continue;
            }
            double time = delay + Geometry.timeUntilWallCollision(segments.get(i), circleAfter(ball, vx, vy, delay),
                    new Vect(vx, vy));
            if (time <= earliest.limit() && closesOnSegment(segments.get(i), ball, vx, vy, time)) {
                earliest.offer(time, ball, new Contact.Face(gizmo, i, segments.get(i)), false);
            }
        }
        List<Circle> circles = shape.circles();
        for (int i = 0; i < circles.size(); i++) {
            if (swept.misses(circles.get(i))
                    || !Approach.mayMeetCircle(circles.get(i), cx, cy, vx, vy, earliest.limit() - delay)) {
                continue;
            }
            double time = delay + Geometry.timeUntilCircleCollision(circles.get(i), circleAfter(ball, vx, vy, delay),
                    new Vect(vx, vy));
            if (time <= earliest.limit() && closingOnCircle(ball, vx, vy, time, circles.get(i).getCenter())) {
                earliest.offer(time, ball, new Contact.Round(gizmo, i, circles.get(i)), true);
            }
        }
    }

    /**
     * A moving shape ({@code gizmo} itself): rotating contacts up to the time it stops (or to the end of the window), then the fixed shape
     * at its stop met by the ball from where it will be at that time.
     */
    private void againstMovingShape(Ball ball, GizmoBase gizmo, MovingShape moving, double window,
                                    Earliest earliest) {
        Circle circle = ball.circle();
        Vect velocity = motion(ball);
        double swingLeft = moving.timeToStop();
        double omega = moving.angularVelocity();
        Vect pivot = moving.pivot();
        Shape now = moving.shape();
        // The rotating search looks only as far as it must: to the end of the swing or of the window.
        GeometryInterface rotating = rotatingSearch(Math.min(swingLeft, window));
        for (int i = 0; i < now.segments().size(); i++) {
            LineSegment side = now.segments().get(i);
            double time = rotating.timeUntilRotatingWallCollision(side, pivot, omega, circle, velocity);
            if (time <= swingLeft && time <= earliest.limit()) {
                Vect centre = ball.position().plus(velocity.times(time));
                LineSegment then = Geometry.rotateAround(side, pivot, new Angle(omega * time));
                Vect foot = Geometry.perpendicularPointWholeLine(then, centre);
                if (closing(centre.minus(foot), velocity.minus(Kinematics.surfaceVelocity(pivot, omega, foot)))) {
                    earliest.offer(time, ball, new Contact.MovingPart(moving, false, i), false);
                }
            }
        }
        for (int i = 0; i < now.circles().size(); i++) {
            Circle end = now.circles().get(i);
            if (moving.turnsInPlace(i)) {
                // Its centre is the pivot: it turns in place, a still circle to the ball.
                double time = Geometry.timeUntilCircleCollision(end, circle, velocity);
                if (time <= earliest.limit()
                        && closingOnCircle(ball, velocity.x(), velocity.y(), time, end.getCenter())) {
                    earliest.offer(time, ball, new Contact.Round(gizmo, i, end), true);
                }
                continue;
            }
            double time = rotating.timeUntilRotatingCircleCollision(end, pivot, omega, circle, velocity);
            if (time <= swingLeft && time <= earliest.limit()) {
                Vect centre = ball.position().plus(velocity.times(time));
                Vect endCentre = Geometry.rotateAround(end.getCenter(), pivot, new Angle(omega * time));
                Vect relative = velocity.minus(Kinematics.surfaceVelocity(pivot, omega, endCentre));
                if (closingOnCircle(centre.minus(endCentre), relative)) {
                    earliest.offer(time, ball, new Contact.MovingPart(moving, true, i), true);
                }
            }
        }
        boolean still = velocity.x() == 0 && velocity.y() == 0;
        if (swingLeft < window && !still) {
            againstStillShape(ball, swingLeft, gizmo, moving.shapeAtStop(), earliest);
        }
    }

    /** physics-lib with the rotating search looking {@code foresight} seconds ahead. */
    private GeometryInterface rotatingSearch(double foresight) {
        if (foresight != rotatingForesight) {
            rotating = new GeometryImpl(foresight, rotatingSearchSlices);
            rotatingForesight = foresight;
        }
        return rotating;
    }

    /**
     * The ball's circle where it will be after {@code delay} seconds at (vx, vy), for a question to physics-lib: made
     * at the question, never kept, so that where the API's method is inlined (physics-lib keeps the hot ones small)
     * the JIT need not make it, nor the velocity made beside it (200 balls in play made 1.6 KB of them a tick).
     * {@code ball.position().plus(velocity.times(delay))} on the components: its own centre for no delay. One vector
     * is made on either way, for the JIT does not take apart objects that two branches made.
     */
    private static Circle circleAfter(Ball ball, double vx, double vy, double delay) {
        Vect centre = delay == 0 ? ball.position() : new Vect(at(ball.x(), vx, delay), at(ball.y(), vy, delay));
        return new Circle(centre, Arena.BALL_RADIUS);
    }

    /**
     * Whether the ball, at the segment's line after {@code time}, closes on it faster than rounding: {@link #closing}
     * of its centre then less the foot of the perpendicular on the whole line, reckoned on the components so that
     * asking every face in reach makes no vector, each step the Vect arithmetic of
     * {@code Geometry.perpendicularPointWholeLine} and of {@code closing}, in the same order, each component of a made
     * vector with Vect's + 0.0 (the same doubles; {@code CollisionDetectorTest} holds the two to it).
     */
    static boolean closesOnSegment(LineSegment segment, Ball ball, double vx, double vy, double time) {
        if (!(time < Double.POSITIVE_INFINITY)) {
            return false;
        }
        double cx = ball.x() + (vx * time + 0.0) + 0.0;
        double cy = ball.y() + (vy * time + 0.0) + 0.0;
        Vect p1 = segment.p1();
        Vect p2 = segment.p2();
        double dirX = p2.x() - p1.x() + 0.0;
        double dirY = p2.y() - p1.y() + 0.0;
        double footX = p1.x();
        double footY = p1.y();
        if (dirX != 0 || dirY != 0) {
            double along = ((cx - p1.x() + 0.0) * dirX + (cy - p1.y() + 0.0) * dirY) / (dirX * dirX + dirY * dirY);
            footX = p1.x() + (dirX * along + 0.0) + 0.0;
            footY = p1.y() + (dirY * along + 0.0) + 0.0;
        }
        double awayX = cx - footX + 0.0;
        double awayY = cy - footY + 0.0;
        double length = awayX == 0 ? Math.abs(awayY) : awayY == 0 ? Math.abs(awayX) : StrictMath.hypot(awayX, awayY);
        return length > 0 && -(vx * awayX + vy * awayY) / length > Tolerances.ROUNDING_SPEED;
    }

    /**
     * Whether a ball moving at {@code relative} to what it touches, on the side {@code away} points to, closes on
     * it faster than rounding: otherwise the touch is a graze and no collision.
     */
    static boolean closing(Vect away, Vect relative) {
        double length = away.length();
        return length > 0 && -relative.dot(away) / length > Tolerances.ROUNDING_SPEED;
    }

    /**
     * As {@link #closing}, for a circle met at {@code away} from its centre: a touch within
     * {@link Tolerances#GRAZE_ANGLE} of tangent is a graze, and so is one that {@link Kinematics#grazes}.
     */
    static boolean closingOnCircle(Vect away, Vect relative) {
        return closingOnCircle(away.x(), away.y(), relative.x(), relative.y());
    }

    /**
     * {@link #closingOnCircle} of the ball, moved on at (vx, vy) for {@code time}, at a circle centred on
     * {@code centre}: {@code ball.position().plus(velocity.times(time)).minus(centre)} on the components.
     */
    private static boolean closingOnCircle(Ball ball, double vx, double vy, double time, Vect centre) {
        return closingOnCircle(at(ball.x(), vx, time) - centre.x() + 0.0, at(ball.y(), vy, time) - centre.y() + 0.0,
                vx + 0.0, vy + 0.0);
    }

    /** One component of {@code position.plus(velocity.times(time))}, with Vect's + 0.0 at each made vector. */
    private static double at(double position, double velocity, double time) {
        return position + 0.0 + (velocity * time + 0.0) + 0.0;
    }

    /** {@link #closingOnCircle(Vect, Vect)} on the components, so that asking it makes no vector. */
    private static boolean closingOnCircle(double awayX, double awayY, double relativeX, double relativeY) {
        double approach = -(relativeX * awayX + relativeY * awayY);
        if (!(approach > 0)) {
            return false;   // the closing speed, approach / |away|, is not positive: no length changes that
        }
        double awaySquared = awayX * awayX + awayY * awayY;
        double speedSquared = relativeX * relativeX + relativeY * relativeY;
        if (awaySquared > TINY_SQUARE && speedSquared > TINY_SQUARE) {
            double length = Math.sqrt(awaySquared);
            double speed = Math.sqrt(speedSquared);
            int closes = clearly(approach / length,
                    Math.max(Tolerances.ROUNDING_SPEED, Tolerances.GRAZE_ANGLE * speed));
            if (closes < 0) {
                return false;
            }
            int grazing = clearly(Math.abs(awayX * relativeY - awayY * relativeX) / speed,
                    length - Tolerances.PLACEMENT);
            if (closes > 0 && grazing != 0) {
                return grazing < 0;
            }
        }
        return closingOnCircleExactly(new Vect(awayX, awayY), new Vect(relativeX, relativeY));
    }

    /**
     * Squares of lengths above this are sums of squares that lost nothing to underflow (board lengths and speeds
     * lie far above it).
     */
    private static final double TINY_SQUARE = 1e-200;
    /** Relative difference far above what the square roots of {@link #closingOnCircle} make (a few 1e-16). */
    private static final double CLEAR = 1e-12;

    /**
     * 1 where {@code a} exceeds {@code b} by more than {@link #CLEAR} of them, -1 where it falls short so, else 0: a
     * comparison that a length by a square root, within a few ulps of physics-lib's hypot, decides as hypot would.
     */
    private static int clearly(double a, double b) {
        double margin = CLEAR * (Math.abs(a) + Math.abs(b));
        return a - b > margin ? 1 : b - a > margin ? -1 : 0;
    }

    /**
     * {@link #closingOnCircle} with the lengths as physics-lib gives them ({@link Vect#length}, a hypot): what decides
     * it where the square roots leave it within rounding, so that the answer is always this one. A ball asks it of
     * every ball it may meet, so the square roots answer first (hypot costs several times as much).
     */
    private static boolean closingOnCircleExactly(Vect away, Vect relative) {
        double length = away.length();
        double closing = length > 0 ? -relative.dot(away) / length : 0;
        return closing > Math.max(Tolerances.ROUNDING_SPEED, Tolerances.GRAZE_ANGLE * relative.length())
                && !Kinematics.grazes(away, relative, length);
    }
}
