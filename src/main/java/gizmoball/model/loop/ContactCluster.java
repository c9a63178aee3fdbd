package gizmoball.model.loop;

import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.MovingShape;
import gizmoball.model.gizmo.Shape;
import gizmoball.model.loop.ClusterRow.Other;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.function.Predicate;

import physics.Circle;
import physics.Geometry;
import physics.LineSegment;
import physics.Vect;

/**
 * The connected set of touching contacts around a ball (docs/design.md, "Contact clusters"): the balls that touch it,
 * the balls that touch those, and so on, with every surface each of them touches: outer walls, still gizmo parts
 * and the parts of moving shapes (swinging flippers), which move the cluster and are not moved by it. A query: it
 * reads positions and velocities and changes nothing.
 */
final class ContactCluster {

    /**
     * The balls that may touch a ball: into {@code into}, in the board's order, every ball whose centre lies within
     * {@code within} of the ball's along x and along y, and perhaps others (the ball itself too).
     */
    @FunctionalInterface
    interface Near {
        void balls(Ball ball, double within, List<Ball> into);
    }

    private final List<Ball> balls = new ArrayList<>();
    private final List<ClusterRow> rows = new ArrayList<>();
    /**
     * Every row made so far, the first {@link #rowsUsed} of them set in this gathering: the rows are kept from one
     * gathering to the next and set afresh ({@link ClusterRow}).
     */
    private final List<ClusterRow> rowPool = new ArrayList<>();
    private int rowsUsed;
    /**
     * Round contacts (a ball, a circle) that the balls graze as they move now: no rows unless the solve turns a ball
     * into one ({@link #takeClosingGrazes}).
     */
    private final List<Graze> grazing = new ArrayList<>();

    /**
     * A graze's row; the offset of the ball's centre from the centre it grazes, how near the two touch, and how that
     * centre moves when it is not a ball of the cluster.
     */
    private record Graze(ClusterRow row, Vect offset, double touch, Vect beyondMotion) {
    }
    /** L: how near counts as touching for this cluster. */
    private double touching;
    /** Where a ball's centre falls on a face, found again for each face in reach. */
    private final Foot foot = new Foot();
    /** {@link LoopSettings#leadTime()}. */
    private double leadTime;
    // Kept from one gathering to the next: the balls a ball may touch, and each ball's index in the cluster.
    private final List<Ball> nearby = new ArrayList<>();
    /** Each index's {@link Other.InCluster}, made once (see {@link #inCluster}). */
    private final List<Other.InCluster> inCluster = new ArrayList<>();
    private final Map<Ball, Integer> indexOf = new IdentityHashMap<>();
    /** The gizmos in reach of the member whose surfaces are being gathered: a list kept from member to member. */
    private final List<GizmoBase> inReach = new ArrayList<>();

    /**
     * Gathers the cluster of {@code seeds} as they are now, in place of the one this held (its lists are kept, so
     * that a solve makes only the rows); {@code motion} gives the velocity each ball moves with this tick
     * (none while asleep); a ball that {@code movable} refuses (one that moves no more in this tick) is taken as a
     * surface. Surfaces and balls within {@code reach} of a ball count as touching it: at least
     * {@link Tolerances#PLACEMENT}. The cluster holds at most {@link LoopSettings#clusterBalls()} balls. {@code near}
     * gives the balls that may touch one. Returns this cluster.
     */
    ContactCluster gather(LoopView view, List<Ball> seeds, Near near, Function<Ball, Vect> motion,
                          Predicate<Ball> movable, double reach, LoopSettings settings) {
        balls.clear();
        rows.clear();
        rowsUsed = 0;
        grazing.clear();
        indexOf.clear();
        nearby.clear();
        this.leadTime = settings.leadTime();
        this.touching = Math.max(Tolerances.PLACEMENT, reach);
        for (int s = 0; s < seeds.size(); s++) {
            Ball seed = seeds.get(s);
            if (!indexOf.containsKey(seed)) {
                indexOf.put(seed, balls.size());
                balls.add(seed);
            }
        }
        for (int i = 0; i < balls.size(); i++) {
            Ball ball = balls.get(i);
            surfaces(view, i, ball, motion);
            double within = 2 * Arena.BALL_RADIUS + touching;
            near.balls(ball, within, nearby);
            for (int n = 0; n < nearby.size(); n++) {
                Ball other = nearby.get(n);
                if (other == ball || other.isCaptured() || view.passingThrough(ball, other)
                        || gap(ball.position(), other.position(), 2 * Arena.BALL_RADIUS) > touching) {
                    continue;
                }
                int j = indexOf.getOrDefault(other, -1);
                if (j >= 0 && j < i) {
                    continue;   // its row was made from the other side
                }
                // ball.position().minus(other.position()).unitSize() (Components.unit), on the components
                double offsetX = ball.x() - other.x() + 0.0;
                double offsetY = ball.y() - other.y() + 0.0;
                double length = Components.length(offsetX, offsetY);
                double normalX = Components.unitPart(offsetX, length);
                double normalY = Components.unitPart(offsetY, length);
                Vect mine = motion.apply(ball);
                Vect theirs = motion.apply(other);
                // Kinematics.grazes(ball.position().minus(other.position()), mine.minus(theirs), 2r), on the
                // components with Vect's + 0.0 at each made vector
                boolean grazes = Kinematics.grazes(ball.x() - other.x() + 0.0, ball.y() - other.y() + 0.0,
                        mine.x() - theirs.x() + 0.0, mine.y() - theirs.y() + 0.0, 2 * Arena.BALL_RADIUS);
                if (j < 0 && balls.size() < settings.clusterBalls() && movable.test(other)) {
                    j = balls.size();
                    balls.add(other);
                    indexOf.put(other, j);
                }
                ClusterRow row = j >= 0 ? row(i, inCluster(j), normalX, normalY, null, 0, 1.0)
                        : row(i, new Other.Beyond(other), normalX, normalY, null,
                        beyondSpeed(motion.apply(other), normalX, normalY), 1.0);
                if (grazes) {
                    grazing.add(new Graze(row, ball.position().minus(other.position()), 2 * Arena.BALL_RADIUS,
                            j >= 0 ? Vect.ZERO : motion.apply(other)));
                } else {
                    rows.add(row);
                }
            }
        }
        return this;
    }

    /**
     * The speed along the normal (toward the cluster's ball) of a row on a ball beyond the cluster that moves at
     * {@code motion}: its own where it moves away, which the cluster's ball may follow, but none where it presses in.
     * The solve moves only the cluster's balls: a ball it does not move, pressing in as a surface does, would push
     * them at its speed and keep it, and with still walls beyond them leave no answer at all (a pocket of more than
     * {@link LoopSettings#clusterBalls()} balls under gravity, the ones beyond falling onto the rest: its cluster met
     * itself again at no time apart to the collision cap, fuzz seeds 1000117, 1000384 and 1000596). Held still, it
     * meets the cluster at once and is solved with its own.
     */
    private static double beyondSpeed(Vect motion, double normalX, double normalY) {
        return Math.min(0, motion.x() * normalX + motion.y() * normalY);   // motion.dot(normal)
    }

    /** The next row of the pool, set. */
    private ClusterRow row(int ball, Other other, double normalX, double normalY, Vect normal, double surfaceSpeed,
                    double restitution) {
        if (rowsUsed == rowPool.size()) {
            rowPool.add(new ClusterRow());
        }
        return rowPool.get(rowsUsed++).set(ball, other, normalX, normalY, normal, surfaceSpeed, restitution);
    }

    /** {@link #row} with the normal a vector already made. */
    private ClusterRow row(int ball, Other other, Vect normal, double surfaceSpeed, double restitution) {
        return row(ball, other, normal.x(), normal.y(), normal, surfaceSpeed, restitution);
    }

    /** The cluster's ball {@code index} as a row's other: made once per index and kept (a value). */
    private Other.InCluster inCluster(int index) {
        while (inCluster.size() <= index) {
            inCluster.add(new Other.InCluster(inCluster.size()));
        }
        return inCluster.get(index);
    }

    List<Ball> balls() {
        return balls;
    }

    List<ClusterRow> rows() {
        return rows;
    }

    /**
     * Makes rows of the grazes that the velocities {@code vx, vy} (by ball of the cluster) turn into collisions, as
     * the detector sees them (closing faster than rounding, and no longer a graze); returns whether there were any.
     * A graze is left out of the rows because a row for it can ask for impulses no other contact allows (two balls
     * passing each other in a slot that fits them exactly), but the solve's impulses on the other contacts can turn
     * a ball into it: the bottom ball of a pile in a corner, a ball
     * falling past it, pushed into it by the pile above, was met again at no time apart 144 times in one tick.
     */
    boolean takeClosingGrazes(double[] vx, double[] vy) {
        boolean took = false;
        for (int i = grazing.size() - 1; i >= 0; i--) {
            Graze graze = grazing.get(i);
            ClusterRow row = graze.row();
            Vect relative = new Vect(vx[row.ball()], vy[row.ball()]).minus(graze.beyondMotion());
            if (row.other() instanceof Other.InCluster in) {
                relative = relative.minus(new Vect(vx[in.index()], vy[in.index()]));
            }
            if (-relative.dot(row.normal()) > Tolerances.ROUNDING_SPEED
                    && !Kinematics.grazes(graze.offset(), relative, graze.touch())) {
                rows.add(grazing.remove(i).row());
                took = true;
            }
        }
        return took;
    }

    private void surfaces(LoopView view, int index, Ball ball, Function<Ball, Vect> motion) {
        Vect p = ball.position();
        for (int side = 0; side < Arena.OUTER_WALLS.size(); side++) {
            still(index, p, Arena.OUTER_WALLS.get(side), side, null);
        }
        double reach = Arena.BALL_RADIUS + touching;
        view.index().within(p.x() - reach, p.y() - reach, p.x() + reach, p.y() + reach, inReach);
        for (int g = 0; g < inReach.size(); g++) {
            GizmoBase gizmo = inReach.get(g);
            if (gizmo.takesBalls()) {
                continue;   // what touches an absorber or a sink is taken by it, not held
            }
            Shape shape = gizmo.shape();
            if (gizmo instanceof MovingShape moving && moving.isMoving()) {
                moving(index, p, motion.apply(ball), moving, shape);
                continue;
            }
            for (int i = 0; i < shape.segments().size(); i++) {
                if (Passages.through(view, ball, gizmo, i) == null) {   // an open mouth with room passes the ball on
                    still(index, p, shape.segments().get(i), i, gizmo);
                }
            }
            for (int i = 0; i < shape.circles().size(); i++) {
                Circle circle = shape.circles().get(i);
                double touch = circle.getRadius() + Arena.BALL_RADIUS;
                ContactRef ref = new ContactRef.Part(gizmo.name(), true, i);
                // A circle the ball lies on is a row however the ball slides along it: the solve may turn it in.
                if (gap(p, circle.getCenter(), touch) <= touching) {
                    Vect normal = p.minus(circle.getCenter()).unitSize();
                    ClusterRow row = row(index, new Other.Still(ref, gizmo), normal, 0, gizmo.reflectionCoefficient());
                    if (!ball.contacts().contains(ref)
                            && Kinematics.grazes(p.minus(circle.getCenter()), motion.apply(ball), touch)) {
                        grazing.add(new Graze(row, p.minus(circle.getCenter()), touch, Vect.ZERO));
                    } else {
                        rows.add(row);
                    }
                }
            }
        }
    }

    /**
     * Segment {@code part} of the gizmo (of the outer walls where it is null) as a row of the ball at {@code p}, if it
     * touches: the foot, the gap and the normal reckoned on the components (each face in reach is asked).
     */
    private void still(int index, Vect p, LineSegment segment, int part, GizmoBase gizmo) {
        if (!foot.on(segment, p.x(), p.y())) {
            return;
        }
        double awayX = p.x() - foot.x + 0.0;   // p.minus(foot)
        double awayY = p.y() - foot.y + 0.0;
        double dx = p.x() - foot.x;   // as p.distanceSquared(foot)
        double dy = p.y() - foot.y;
        if (Math.sqrt(dx * dx + dy * dy) - Arena.BALL_RADIUS <= touching) {
            ContactRef ref = gizmo == null ? ContactRef.Wall.of(part) : new ContactRef.Part(gizmo.name(), false, part);
            double length = Components.length(awayX, awayY);   // Components.unit(awayX, awayY), on the components
            double restitution = gizmo == null ? 1.0 : gizmo.reflectionCoefficient();
            rows.add(row(index, new Other.Still(ref, gizmo), Components.unitPart(awayX, length),
                    Components.unitPart(awayY, length), null, 0, restitution));
        }
    }

    /**
     * The speed a ball must leave a moving part's face with, along its normal n: the surface's own speed there, and
     * what the surface gains on the ball over {@link LoopSettings#leadTime()}. The distance from a ball moving in a
     * straight line at v to a line turning at omega about the pivot changes at d'' = 2 omega (v . t) - omega^2 (p -
     * pivot) . n, t being n turned a quarter the way omega turns: a ball left at only the surface's speed is met again
     * at once where d'' &lt; 0. The second term is a ball at rest in the way of a turning line (a flipper sweeping a
     * ball along a wall beside it would strike it every microsecond); the first a ball sliding along the line away from
     * the pivot as it turns into the ball (one fired along a spinner's bar at 40 L/s was struck every 33 us, 250 times
     * a tick).
     */
    private double leavingFace(Vect pivot, double omega, Vect p, Vect normal, Vect foot, Vect velocity) {
        return Kinematics.surfaceVelocity(pivot, omega, foot).dot(normal)
                + Math.max(0, gaining(pivot, omega, p, normal, velocity)) * leadTime;
    }

    /** L/s^2: -d'' above, how fast a face turning at omega through p with normal n closes on a ball moving at v. */
    static double gaining(Vect pivot, double omega, Vect p, Vect normal, Vect velocity) {
        Vect tangent = new Vect(-normal.y(), normal.x());
        return omega * omega * p.minus(pivot).dot(normal) - 2 * omega * velocity.dot(tangent);
    }

    /**
     * The same for a moving part's round end, centre q: the end's centre turns toward the pivot at omega^2 (q -
     * pivot), which takes it away from a ball beyond it, and the ball's sliding round it carries it off the circle,
     * so only what the surface gains as at a face is kept, from the ball's centre (more than the end gains).
     */
    private double leavingEnd(Vect pivot, double omega, Vect p, Vect normal, Vect point) {
        double along = p.minus(pivot).dot(normal);
        return Kinematics.surfaceVelocity(pivot, omega, point).dot(normal)
                + omega * omega * Math.max(0, along) * leadTime;
    }

    private void moving(int index, Vect p, Vect velocity, MovingShape moving, Shape shape) {
        Vect pivot = moving.pivot();
        double omega = moving.angularVelocity();
        for (LineSegment side : shape.segments()) {
            Vect foot = Geometry.perpendicularPoint(side, p);
            if (foot != null && gap(p, foot, Arena.BALL_RADIUS) <= touching) {
                Vect normal = p.minus(foot).unitSize();
                rows.add(row(index, new Other.Moving(moving), normal,
                        leavingFace(pivot, omega, p, normal, foot, velocity),
                        moving.reflectionCoefficient()));
            }
        }
        for (Circle end : shape.circles()) {
            if (gap(p, end.getCenter(), end.getRadius() + Arena.BALL_RADIUS) <= touching) {
                Vect normal = p.minus(end.getCenter()).unitSize();
                Vect point = end.getCenter().plus(normal.times(end.getRadius()));
                rows.add(row(index, new Other.Moving(moving), normal, leavingEnd(pivot, omega, p, normal, point),
                        moving.reflectionCoefficient()));
            }
        }
    }

    private static double gap(Vect p, Vect q, double touch) {
        return Math.sqrt(p.distanceSquared(q)) - touch;
    }
}
