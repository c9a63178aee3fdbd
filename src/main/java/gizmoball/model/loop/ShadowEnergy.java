package gizmoball.model.loop;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Function;

import physics.Vect;

/**
 * Keeps the energy of elastic bounces (docs/design.md, "Failure modes": energy drift). In free flight the
 * integration (gravity, then a straight move) keeps the shadow energy |u|^2/2 - g . p exactly, u being the velocity
 * half a gravity kick back; an elastic bounce part-way through a tick moves it by up to g dt |v| either way, and
 * many such bounces would random-walk the energy. So the balls whose collisions in a tick were all elastic (with
 * still shapes of coefficient 1 or with each other) get the normal component of their last bounce adjusted at the
 * end of the tick to keep it; their tangential velocity is never touched. One per tick. A ball that slid on still
 * contacts through the tick keeps the shadow energy as well ({@link Contacts#slidesOnStill}) and is corrected along
 * them.
 *
 * <p>Its books allocate nothing in the steady state (issue 39): what it notes of a ball in a tick is kept on the ball
 * ({@link Ball.EnergyMarks}), stamped with the tick's number, so a stamp of another tick means "nothing noted"; the
 * lists are kept from tick to tick.
 */
final class ShadowEnergy {
    private long tick;
    private Vect gravity;
    private double dt;
    /** The balls with an elastic bounce this tick, in order of first bounce (runs stay bit-identical). */
    private final List<Ball> bouncers = new ArrayList<>();
    /** The balls that lost energy this tick, in order of first loss: {@link #capLosses} reads them. */
    private final List<Ball> losers = new ArrayList<>();
    /** The balls that met each other, two by two. */
    private final List<Ball> pairs = new ArrayList<>();
    /** The groups of {@link #restore()}, by index: lists kept from tick to tick. */
    private final List<List<Ball>> groups = new ArrayList<>();
    /** The balls of a group that take a correction, and the direction each takes, side by side (kept, grown). */
    private final List<Ball> correctable = new ArrayList<>();
    private double[] directionsX = new double[0];
    private double[] directionsY = new double[0];
    /** What {@link #direction} found. */
    private double directionX;
    private double directionY;
    /** {@link LoopSettings#slidingPart()}. */
    private final double slidingPart;

    ShadowEnergy(LoopSettings settings) {
        this.slidingPart = settings.slidingPart();
    }

    /**
     * Tick {@code number} ({@link StepContext#tick}), of {@code seconds} under this gravity, starts: the books are
     * emptied (kept at the size they grew to).
     */
    void begin(Vect boardGravity, double seconds, long number) {
        tick = number;
        gravity = boardGravity;
        dt = seconds;
        bouncers.clear();
        losers.clear();
        pairs.clear();
    }

    /**
     * After stage 1: right after the gravity kick, u = v - g dt/2. (The arithmetic of {@code Vect}'s minus, times and
     * dot on the components, in the same order: the same doubles.)
     */
    void start(Ball ball) {
        double half = dt / 2;
        double ux = ball.vx() - (gravity.x() * half + 0.0);
        double uy = ball.vy() - (gravity.y() * half + 0.0);
        Ball.EnergyMarks marks = ball.energyMarks();
        marks.atStart = (ux * ux + uy * uy) / 2 - (gravity.x() * ball.x() + gravity.y() * ball.y());
        marks.startedIn = tick;
    }

    /**
     * The ball lost energy this tick (a lossy surface, a rest, a capture, a flipper): no elastic correction; it ends
     * with no more shadow energy than it began with unless something may have given it some ({@link #mayGain}).
     */
    void lost(Ball ball) {
        Ball.EnergyMarks marks = ball.energyMarks();
        if (marks.lostIn != tick) {
            marks.lostIn = tick;
            losers.add(ball);
        }
    }

    /**
     * Something this tick may have given the ball energy, or moved energy between it and other balls: a moving shape,
     * a booster, a portal, a ball it met. Its losses are not capped ({@link #capLosses}).
     */
    void mayGain(Ball ball) {
        ball.energyMarks().mayGainIn = tick;
    }

    /** A bounce with the given normal (from the surface to the ball). */
    void bounced(Ball ball, Vect normal, boolean elastic) {
        if (!elastic) {
            lost(ball);
            return;
        }
        bounced(ball, normal.x(), normal.y());
    }

    /**
     * An elastic bounce with the normal (normalX, normalY), as a {@code Vect} holds it: the books keep the components,
     * so a pair's bounce, reckoned on them, makes no vector.
     */
    void bounced(Ball ball, double normalX, double normalY) {
        Ball.EnergyMarks marks = ball.energyMarks();
        if (marks.bouncedIn != tick) {
            marks.bouncedIn = tick;
            bouncers.add(ball);
        }
        marks.normalX = normalX;
        marks.normalY = normalY;
    }

    /** Two balls bounced off each other: their energy is kept together, not each one's. */
    void met(Ball ball, Ball other) {
        pairs.add(ball);
        pairs.add(other);
    }


    /**
     * Adjusts each group of balls that met each other (or a ball alone). Ball-ball collisions conserve a group's
     * total, so the group shares one correction: each velocity moves by lambda along the normal of the ball's last
     * bounce (opposite normals for a pair, so momentum is kept), with w_i = v_i + g dt/2 (u at the end of a tick)
     * and sum |w_i + lambda n_i|^2 = sum 2 (S_i + g . p_i).
     */
    void restore(Function<Ball, List<Vect>> contactNormals) {
        // Each bouncer starts a group of its own; a pair joins the second's group to the end of the first's. The
        // groups are then corrected in the order of their earliest bouncer, each in the order its balls joined.
        for (int i = 0; i < bouncers.size(); i++) {
            if (groups.size() == i) {
                groups.add(new ArrayList<>());
            }
            List<Ball> group = groups.get(i);
            group.clear();
            group.add(bouncers.get(i));
            bouncers.get(i).energyMarks().group = i;
        }
        for (int k = 0; k < pairs.size(); k += 2) {
            int first = pairs.get(k).energyMarks().group;
            int second = pairs.get(k + 1).energyMarks().group;
            if (first != second) {
                List<Ball> joining = groups.get(second);
                for (int j = 0; j < joining.size(); j++) {
                    groups.get(first).add(joining.get(j));
                    joining.get(j).energyMarks().group = first;
                }
                joining.clear();
            }
        }
        for (int i = 0; i < bouncers.size(); i++) {
            Ball ball = bouncers.get(i);
            List<Ball> group = groups.get(ball.energyMarks().group);
            if (!group.isEmpty()) {
                restore(group, contactNormals);
                group.clear();   // corrected: its other balls pass it over
            }
        }
        capLosses();
    }

    /**
     * A ball that only lost energy this tick, against still surfaces (a rest, a bounce of coefficient below 1), ends
     * with no more shadow energy than it began with. Such a collision part-way through a tick moves S by
     * (s - 1/2) dt g . dv as an elastic one does, and for a bounce up early in a tick that is more than the bounce
     * loses: on stress.txt a ball in the wedge between a resting flipper's end and a triangle's slope gained 0.34 at
     * each bounce, more than the flipper and friction took, and rocked there for ever. Its velocity is scaled, its
     * direction kept, so it closes on nothing it did not close on, and only by a timing error's size.
     */
    private void capLosses() {
        double hx = gravity.x() * (dt / 2) + 0.0;
        double hy = gravity.y() * (dt / 2) + 0.0;
        double timingSpeed = 2 * gravity.length() * dt;
        for (int i = 0; i < losers.size(); i++) {
            Ball ball = losers.get(i);
            Ball.EnergyMarks marks = ball.energyMarks();
            double vx = ball.vx();
            double vy = ball.vy();
            double squares = vx * vx + vy * vy;
            if (marks.mayGainIn == tick || marks.startedIn != tick || ball.isCaptured() || squares == 0) {
                continue;
            }
            double target = 2 * (marks.atStart + (gravity.x() * ball.x() + gravity.y() * ball.y()));
            double wx = vx + hx;
            double wy = vy + hy;
            if (wx * wx + wy * wy <= target) {
                continue;
            }
            // |k v + h|^2 = target: squares k^2 + 2 (v . h) k + |h|^2 - target = 0; the larger root lies below 1
            double vh = vx * hx + vy * hy;
            double discriminant = vh * vh - squares * (hx * hx + hy * hy - target);
            if (discriminant < 0) {
                continue;
            }
            double k = (-vh + Math.sqrt(discriminant)) / squares;
            if (k >= 0 && k < 1 && (1 - k) * Math.sqrt(squares) <= timingSpeed) {
                ball.setVelocity(vx * k, vy * k);
            }
        }
    }

    /**
     * The direction a ball's correction takes: the normal of its last bounce, or for a ball that slides on contacts
     * that normal's part along them, so that the correction never presses it into them nor lifts it off (a ball
     * sliding down a slope into a wall goes back up the slope). Null where no such part is left: two contacts that
     * hold it in the plane (a ball lying in a notch, met by another), and it takes no correction. Returns whether it
     * has one, found in ({@link #directionX}, {@link #directionY}) as a {@code Vect} would hold it.
     */
    private boolean direction(Ball ball, Function<Ball, List<Vect>> contactNormals) {
        Ball.EnergyMarks marks = ball.energyMarks();
        if (marks.bouncedIn != tick) {
            return false;   // no elastic bounce this tick
        }
        List<Vect> contacts = contactNormals.apply(ball);
        if (contacts.isEmpty()) {
            directionX = marks.normalX;
            directionY = marks.normalY;
            return true;
        }
        // along = along.minus(c.times(along.dot(c))) for each contact c, on the components with Vect's + 0.0
        double alongX = marks.normalX;
        double alongY = marks.normalY;
        for (int i = 0; i < contacts.size(); i++) {
            Vect c = contacts.get(i);
            double part = alongX * c.x() + alongY * c.y();
            alongX = alongX - (c.x() * part + 0.0) + 0.0;
            alongY = alongY - (c.y() * part + 0.0) + 0.0;
        }
        for (int i = 0; i < contacts.size(); i++) {
            Vect c = contacts.get(i);
            if (Math.abs(alongX * c.x() + alongY * c.y()) > Tolerances.TANGENT_ROUNDING) {
                return false;   // not along all of them at once
            }
        }
        double length = Components.length(alongX, alongY);
        if (length < slidingPart) {
            return false;
        }
        double inverse = 1 / length;
        directionX = alongX * inverse + 0.0;
        directionY = alongY * inverse + 0.0;
        return true;
    }

    /**
     * Where no correction along the bounce's normal reaches S (a ball bouncing early in a tick off both sides of a
     * wedge at once, whose timing moved S by more than that normal's part of |w|^2 can take back), a ball alone and
     * in free flight has its whole w = v + g dt/2 scaled instead, direction kept, if that is a timing error's size.
     */
    private void scaleAlone(List<Ball> group, Function<Ball, List<Vect>> contactNormals, double squares,
                            double target, double timingSpeed) {
        if (group.size() != 1 || target <= 0 || squares <= 0 || !contactNormals.apply(group.get(0)).isEmpty()) {
            return;
        }
        double scale = Math.sqrt(target / squares);
        if (Math.abs(scale - 1) * Math.sqrt(squares) > timingSpeed) {
            return;
        }
        Ball ball = group.get(0);
        Vect h = gravity.times(dt / 2);
        ball.setVelocity(ball.velocity().plus(h).times(scale).minus(h));
    }

    /**
     * Corrects the group's balls that can take a correction (a direction), all by the same amount, so that the
     * group's total S is what it was at the start; a ball held by its contacts keeps its velocity but counts in the
     * total.
     */
    private void restore(List<Ball> group, Function<Ball, List<Vect>> contactNormals) {
        // h = g dt/2 and w = v + h on the components: the doubles of Vect's times, plus and dot
        double hx = gravity.x() * (dt / 2) + 0.0;
        double hy = gravity.y() * (dt / 2) + 0.0;
        double squares = 0;
        double along = 0;
        double target = 0;
        correctable.clear();
        for (int i = 0; i < group.size(); i++) {
            Ball ball = group.get(i);
            Ball.EnergyMarks marks = ball.energyMarks();
            if (marks.lostIn == tick || ball.isCaptured() || marks.startedIn != tick) {
                return;
            }
            double wx = ball.vx() + hx + 0.0;
            double wy = ball.vy() + hy + 0.0;
            squares += wx * wx + wy * wy;
            target += 2 * (marks.atStart + (gravity.x() * ball.x() + gravity.y() * ball.y()));
            if (direction(ball, contactNormals)) {
                int k = correctable.size();
                if (directionsX.length == k) {
                    directionsX = Arrays.copyOf(directionsX, 2 * k + 1);
                    directionsY = Arrays.copyOf(directionsY, 2 * k + 1);
                }
                correctable.add(ball);
                directionsX[k] = directionX;
                directionsY[k] = directionY;
                along += wx * directionX + wy * directionY;
            }
        }
        if (correctable.isEmpty()) {
            return;
        }
        // A bounce at a fraction s of the tick changing v by dv moves S by (s - 1/2) dt g . dv, at most dt |g| |v_n|
        // for an elastic one: a correction of about |g| dt along the bounce's normal. Twice that allows for a few
        // bounces in one tick and a sliding ball's correction along its surface.
        double timingSpeed = 2 * gravity.length() * dt;
        int n = correctable.size();
        double discriminant = along * along - n * (squares - target);
        if (discriminant < 0) {
            scaleAlone(group, contactNormals, squares, target, timingSpeed);
            return;
        }
        double root = Math.sqrt(discriminant);
        double lambda = Math.abs(-along + root) <= Math.abs(-along - root) ? (-along + root) / n : (-along - root) / n;
        for (int i = 0; i < n; i++) {
            Ball ball = correctable.get(i);
            double normalSpeed = ball.vx() * directionsX[i] + ball.vy() * directionsY[i];
            if (normalSpeed + lambda < 0 || Math.abs(lambda) > Math.max(normalSpeed / 2, timingSpeed)) {
                return;   // not a rounding of the bounce timing: leave the group alone
            }
        }
        for (int i = 0; i < n; i++) {
            Ball ball = correctable.get(i);
            ball.setVelocity(ball.vx() + (directionsX[i] * lambda + 0.0), ball.vy() + (directionsY[i] * lambda + 0.0));
        }
    }
}
