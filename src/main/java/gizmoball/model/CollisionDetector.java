package gizmoball.model;

import java.util.Collection;
import java.util.List;
import java.util.Set;

import physics.Circle;
import physics.Geometry;
import physics.GeometryImpl;
import physics.GeometryInterface;
import physics.LineSegment;
import physics.Vect;

/**
 * Stage 3 of the loop, for one ball: the time until it hits the outer walls, each gizmo shape it can reach, or
 * another ball. All times come from physics.Geometry. A moving flipper
 * is asked through the rotating methods of a GeometryImpl whose foresight ends with its swing (the library assumes
 * the rotation goes on for ever, pitfall 3); after that it is a fixed shape at its limit.
 */
final class CollisionDetector {
    /** Margin around a ball's swept box when asking the spatial index (touching shapes must be found). */
    private static final double REACH_MARGIN = 1e-6;
    /**
     * Slices of a flipper's swing over which the rotating search bounds the ball's motion. Any value finds the
     * same contacts; more slices take fewer search steps for fast balls. Ours, because the API has no constant.
     */
    private static final int ROTATING_SEARCH_SLICES = 16;

    private static final List<LineSegment> OUTER_WALLS = List.of(
            new LineSegment(0, 0, Board.SIZE, 0),
            new LineSegment(Board.SIZE, 0, Board.SIZE, Board.SIZE),
            new LineSegment(Board.SIZE, Board.SIZE, 0, Board.SIZE),
            new LineSegment(0, Board.SIZE, 0, 0));

    private final Board board;
    private final Set<Flipper> stoppedFlippers;
    private final Set<Ball> stoppedBalls;
    private final Set<Touch> settled;

    /** A ball touching what it would hit. */
    record Touch(Ball ball, Contact contact) {
    }

    /**
     * @param stoppedFlippers flippers held still for the rest of the tick (pinched balls), treated as fixed
     * @param stoppedBalls    balls that move no more this tick, treated as at rest
     * @param settled         touches whose zero-time collision was resolved without changing any velocity: they
     *                        close at a rounding of the velocity, so a zero-time collision of theirs is no collision
     */
    CollisionDetector(Board board, Set<Flipper> stoppedFlippers, Set<Ball> stoppedBalls, Set<Touch> settled) {
        this.board = board;
        this.stoppedFlippers = stoppedFlippers;
        this.stoppedBalls = stoppedBalls;
        this.settled = settled;
    }

    /** The velocity the ball moves with for the rest of the tick. */
    private Vect motion(Ball ball) {
        return stoppedBalls.contains(ball) ? Vect.ZERO : ball.velocity();
    }

    /** The ball's earliest collision with the outer walls or a gizmo within the window. */
    Earliest againstScene(Ball ball, double window) {
        Earliest earliest = new Earliest(window);
        againstWallsAndGizmos(ball, window, earliest);
        return earliest;
    }

    /** The two balls' collision, if it comes within the window, offered to {@code earliest} as {@code ball}'s. */
    void againstBall(Ball ball, Ball other, double window, Earliest earliest) {
        Vect relative = motion(ball).minus(motion(other));
        double gap = Math.sqrt(ball.position().distanceSquared(other.position())) - 2 * Board.BALL_RADIUS;
        if (gap > relative.length() * window + REACH_MARGIN) {
            return;   // cannot close the gap within the window
        }
        double time = Geometry.timeUntilBallBallCollision(ball.circle(), motion(ball), other.circle(), motion(other));
        offer(earliest, time, ball, new Contact.OtherBall(other), true);
    }

    /**
     * Offers a collision unless it is a settled touch at zero time: resolving it again would change nothing, and
     * the loop would meet it again and again without time passing.
     */
    private void offer(Earliest earliest, double time, Ball ball, Contact contact, boolean circle) {
        if (time <= TickRun.ZERO_TIME && settled.contains(new Touch(ball, contact))) {
            return;
        }
        earliest.offer(time, ball, contact, circle);
    }

    boolean isMoving(Flipper flipper) {
        return flipper.isMoving() && !stoppedFlippers.contains(flipper);
    }

    private void againstWallsAndGizmos(Ball ball, double window, Earliest earliest) {
        Circle circle = ball.circle();
        Vect velocity = motion(ball);
        boolean still = velocity.x() == 0 && velocity.y() == 0;
        if (!still) {
            for (LineSegment wall : OUTER_WALLS) {
                offer(earliest, Geometry.timeUntilWallCollision(wall, circle, velocity), ball,
                        new Contact.Wall(wall, null), false);
            }
        }
        for (GizmoBase gizmo : reachable(ball, window)) {
            if (gizmo instanceof Flipper flipper && isMoving(flipper)) {
                againstSwingingFlipper(ball, flipper, window, earliest);
            } else if (!still) {
                againstFixedShape(ball, circle, velocity, 0, gizmo, gizmo.shape(), earliest);
            }
        }
    }

    /** The gizmos whose cells meet the box the ball sweeps in the window (all gizmos without the index). */
    private Collection<GizmoBase> reachable(Ball ball, double window) {
        if (!board.spatialIndexEnabled()) {
            return board.gizmoBases();
        }
        Vect from = ball.position();
        Vect to = from.plus(motion(ball).times(window));
        double reach = Board.BALL_RADIUS + REACH_MARGIN;
        return board.index().within(Math.min(from.x(), to.x()) - reach, Math.min(from.y(), to.y()) - reach,
                Math.max(from.x(), to.x()) + reach, Math.max(from.y(), to.y()) + reach);
    }

    /** A shape that does not move; {@code delay}: the ball's circle is where the ball will be after that time. */
    private void againstFixedShape(Ball ball, Circle circle, Vect velocity, double delay, GizmoBase gizmo,
                                   Shape shape, Earliest earliest) {
        List<LineSegment> segments = shape.segments();
        for (int i = 0; i < segments.size(); i++) {
            double time = delay + Geometry.timeUntilWallCollision(segments.get(i), circle, velocity);
            offer(earliest, time, ball, gizmo instanceof Flipper flipper ? new Contact.FlipperPart(flipper, false, i)
                    : new Contact.Wall(segments.get(i), gizmo), false);
        }
        List<Circle> circles = shape.circles();
        for (int i = 0; i < circles.size(); i++) {
            double time = delay + Geometry.timeUntilCircleCollision(circles.get(i), circle, velocity);
            offer(earliest, time, ball, gizmo instanceof Flipper flipper ? new Contact.FlipperPart(flipper, true, i)
                    : new Contact.Round(circles.get(i), gizmo), true);
        }
    }

    /**
     * A swinging flipper: rotating contacts up to the time it stops (pitfall 3), then the fixed shape at its limit
     * met by the ball from where it will be at that time.
     */
    private void againstSwingingFlipper(Ball ball, Flipper flipper, double window, Earliest earliest) {
        Circle circle = ball.circle();
        Vect velocity = motion(ball);
        double swingLeft = flipper.timeToStop();
        double omega = flipper.angularVelocity();
        Vect pivot = flipper.pivot();
        Shape now = flipper.shape();
        // The rotating search looks only as far as it must: to the end of the swing or of the window.
        GeometryInterface rotating = new GeometryImpl(Math.min(swingLeft, window), ROTATING_SEARCH_SLICES);
        for (int i = 0; i < now.segments().size(); i++) {
            double time = rotating.timeUntilRotatingWallCollision(now.segments().get(i), pivot, omega, circle, velocity);
            if (time <= swingLeft) {
                offer(earliest, time, ball, new Contact.FlipperPart(flipper, false, i), false);
            }
        }
        for (int i = 0; i < now.circles().size(); i++) {
            double time = rotating.timeUntilRotatingCircleCollision(now.circles().get(i), pivot, omega, circle,
                    velocity);
            if (time <= swingLeft) {
                offer(earliest, time, ball, new Contact.FlipperPart(flipper, true, i), true);
            }
        }
        boolean still = velocity.x() == 0 && velocity.y() == 0;
        if (swingLeft < window && !still) {
            Circle later = new Circle(circle.getCenter().plus(velocity.times(swingLeft)), circle.getRadius());
            againstFixedShape(ball, later, velocity, swingLeft, flipper, flipper.shapeAtStop(), earliest);
        }
    }

}
