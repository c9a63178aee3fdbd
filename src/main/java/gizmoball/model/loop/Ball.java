package gizmoball.model.loop;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

import physics.Circle;
import physics.Vect;

/**
 * A ball: centre and velocity in L and L/s, radius {@link Arena#BALL_RADIUS}; captured while an absorber holds it.
 * A free ball also carries its loop bookkeeping: the surfaces it is in persistent contact with, how long it
 * has been still on them, and whether it sleeps (docs/design.md, "Sleeping").
 */
public final class Ball implements BallView {
    private final String name;
    /**
     * The centre's coordinates (as {@link Vect} keeps them, -0 as +0), and the centre as a {@link Vect}, made when
     * asked for: stage 2 moves every awake ball to each collision of a tick, and a new vector for each of those moves
     * was most of what a tick allocated on a board of 200 balls. The vector is the centre while its coordinates are
     * the centre's, and is made again when read after a move: a move only writes the two doubles. While the loop has
     * the ball filed in a tick ({@link #file}), the coordinates are in its slot of {@code motions}, else in (x, y).
     * The last books it was filed in are kept after the tick (a flag says whether it is filed in them now): storing a
     * reference costs the collector's write barrier, and the loop files the same books tick after tick.
     */
    private double x;
    private double y;
    private Motions motions;
    private boolean filed;
    private Vect position;
    /** Its circle at {@link #position}, made when first asked for there (while its centre is that vector). */
    private Circle circle;
    private Contact.OtherBall asContact;
    private ContactRef.OnBall asSupported;
    private Struck.OtherBall asStruck;
    /**
     * The velocity's components (as {@link Vect} keeps them), and the velocity as a {@link Vect}, made when asked for:
     * stage 1 changes the velocity of every awake ball in every tick.
     */
    private double vx;
    private double vy;
    private Vect velocity;
    private boolean captured;
    private final List<ContactRef> contacts = new ArrayList<>();
    /** Seconds the ball has lain still on its contacts. */
    private double stillTime;
    private boolean asleep;
    /** Moves no more in this tick: {@link FinishedBalls} marks it and clears it (a mark kept on the ball). */
    boolean finished;
    /** Index of the ball among the free balls of the tick running now (the collision schedule's bookkeeping). */
    private int slot;
    /**
     * How many times any ball was made, fell asleep or woke (a capture and a release wake it), on every board: a loop
     * that finds the count where it was when it last counted its free and awake balls knows they are as they were,
     * and does not count 200 balls again at every trigger. Another board's changes only make it count again.
     */
    private static final AtomicLong STATE_CHANGES = new AtomicLong();

    /** A free ball, awake, in contact with nothing. For the board, not for views. */
    public Ball(String name, Vect position, Vect velocity) {
        this.name = name;
        keepVelocity(velocity);
        moveTo(position);
        STATE_CHANGES.incrementAndGet();
    }

    /** A copy with the same state and contacts (for a copy of the board). For the board, not for views. */
    public Ball copy() {
        Ball copy = new Ball(name, position(), velocity());
        copy.captured = captured;
        copy.contacts.addAll(contacts);
        copy.stillTime = stillTime;
        copy.asleep = asleep;
        return copy;
    }

    public String name() {
        return name;
    }

    public Vect position() {
        double cx = x();
        double cy = y();
        if (position == null || position.x() != cx || position.y() != cy) {
            position = new Vect(cx, cy);
        }
        return position;
    }

    /** The centre's x in L, as {@link #position()} has it, without making a vector. */
    public double x() {
        return filed ? motions.x[slot] : x;
    }

    /** The centre's y in L, as {@link #position()} has it, without making a vector. */
    public double y() {
        return filed ? motions.y[slot] : y;
    }

    public Vect velocity() {
        if (velocity == null) {
            velocity = new Vect(vx, vy);
        }
        return velocity;
    }

    /** The velocity's x in L/s, as {@link #velocity()} has it, without making a vector. */
    double vx() {
        return vx;
    }

    /** The velocity's y in L/s, as {@link #velocity()} has it, without making a vector. */
    double vy() {
        return vy;
    }

    public double radius() {
        return Arena.BALL_RADIUS;
    }

    public boolean isCaptured() {
        return captured;
    }

    /** True while the ball lies still in contact and the loop leaves it alone until something can reach it. */
    public boolean isAsleep() {
        return asleep;
    }

    List<ContactRef> contacts() {
        return contacts;
    }

    double stillTime() {
        return stillTime;
    }

    void setStillTime(double seconds) {
        stillTime = seconds;
    }

    int slot() {
        return slot;
    }

    /**
     * Filed in slot {@code index} of a tick's {@code books}: its centre and the velocity it moves with are kept there
     * until {@link #unfile}, and stage 2 moves them with every other filed ball's.
     */
    void file(Motions books, int index) {
        double cx = x();
        double cy = y();
        slot = index;
        if (motions != books) {
            motions = books;
        }
        filed = true;
        books.use(index);
        books.x[index] = cx;
        books.y[index] = cy;
        motionChanged();
    }

    /** Its centre back in the ball, where it lies: the tick that filed it is over. */
    void unfile() {
        if (filed) {
            x = x();
            y = y();
            filed = false;
        }
    }

    /** A filed ball's slot moves with its velocity while it is free and awake, and not at all otherwise. */
    private void motionChanged() {
        if (filed) {
            boolean moves = !captured && !asleep;
            motions.vx[slot] = moves ? vx : 0;
            motions.vy[slot] = moves ? vy : 0;
        }
    }

    /** {@link #STATE_CHANGES} now. */
    static long stateChanges() {
        return STATE_CHANGES.get();
    }

    void fallAsleep() {
        asleep = true;
        STATE_CHANGES.incrementAndGet();
        keepVelocity(Vect.ZERO);
    }

    /** Awake again, contacts kept (the loop checks them at the next tick), stillness counted from zero. */
    void wake() {
        asleep = false;
        stillTime = 0;
        STATE_CHANGES.incrementAndGet();
        motionChanged();
    }

    /** Forgets every contact and wakes: the board changed under the ball. */
    void disturb() {
        contacts.clear();
        wake();
    }

    /** Its circle where it is, made once per place (detection asks for it against every shape in reach). */
    Circle circle() {
        Vect centre = position();
        if (circle == null || circle.getCenter() != centre) {
            circle = new Circle(centre, Arena.BALL_RADIUS);
        }
        return circle;
    }

    /** A reference to this ball as what another lies on, made once (a reference is a value). */
    ContactRef.OnBall asSupported() {
        if (asSupported == null) {
            asSupported = new ContactRef.OnBall(name);
        }
        return asSupported;
    }

    /** This ball as what another ball struck, made once (what was struck is a value). */
    Struck.OtherBall asStruck() {
        if (asStruck == null) {
            asStruck = new Struck.OtherBall(name);
        }
        return asStruck;
    }

    /** This ball as what another ball is about to meet, made once (a contact is a value). */
    Contact.OtherBall asContact() {
        if (asContact == null) {
            asContact = new Contact.OtherBall(this);
        }
        return asContact;
    }

    /**
     * What the loop's {@link ShadowEnergy} noted of this ball, each note stamped with the tick it was made in (a stamp
     * of another tick: nothing noted). Kept on the ball, as a physics engine keeps a body's solver data on the body,
     * so that the books allocate nothing tick after tick. A copy of the ball starts with none.
     */
    static final class EnergyMarks {
        long startedIn;
        /** The shadow energy after stage 1, when {@link #startedIn} is this tick. */
        double atStart;
        long lostIn;
        /** A tick in which something may have given it energy: a moving shape, a booster, a portal, another ball. */
        long mayGainIn;
        long bouncedIn;
        /** The normal of the last elastic bounce, when {@link #bouncedIn} is this tick (as a {@code Vect} holds it). */
        double normalX;
        double normalY;
        /** Its group's index while the tick's groups are formed. */
        int group;
    }

    private final EnergyMarks energyMarks = new EnergyMarks();
    private final KnownNormals knownNormals = new KnownNormals();

    /** The normals its contacts last gave it, for the contact queries ({@link KnownNormals}). */
    KnownNormals knownNormals() {
        return knownNormals;
    }

    EnergyMarks energyMarks() {
        return energyMarks;
    }

    /**
     * What the loop counted of this ball in a tick ({@link StepContext}): kept on the ball as {@link EnergyMarks} are,
     * valid while {@link #tick} is the tick's number.
     */
    static final class CollisionMarks {
        long tick;
        /** Seconds since the tick began when its last collision was resolved. */
        double lastAt;
        /** Its collisions, and those at zero time, in the tick. */
        int collisions;
        int zeroTimeHits;
        /** Whether it has had a collision in the tick. */
        boolean collided;
    }

    private final CollisionMarks collisionMarks = new CollisionMarks();

    /** Its marks of tick {@code tick}: emptied when they were another tick's. */
    CollisionMarks collisionMarks(long tick) {
        if (collisionMarks.tick != tick) {
            collisionMarks.tick = tick;
            collisionMarks.collisions = 0;
            collisionMarks.zeroTimeHits = 0;
            collisionMarks.collided = false;
        }
        return collisionMarks;
    }

    /** The centre moves there, the velocity kept. For the board and its loop, not for views. */
    public void moveTo(Vect newPosition) {
        position = newPosition;
        if (filed) {
            motions.x[slot] = newPosition.x();
            motions.y[slot] = newPosition.y();
        } else {
            x = newPosition.x();
            y = newPosition.y();
        }
    }

    /**
     * Sets the velocity, its speed clamped to {@link Arena#MAX_SPEED}. A clamped velocity can measure a rounding error
     * over the limit; it is kept as it is (the invariants the tests check allow for it), so clamping twice changes
     * nothing and a saved ball reloads with exactly its velocity. Components below {@link Tolerances#NEGLIGIBLE_SPEED}
     * become 0: friction shrinks a leftover component geometrically toward the subnormal range, where the time until it
     * crosses the board overflows (a 1e-308 L/s drift meets a wall after more than 1e308 s). For the board and its
     * loop, not for views.
     */
    public void setVelocity(Vect newVelocity) {
        setVelocity(newVelocity.x(), newVelocity.y());
        if (vx == newVelocity.x() && vy == newVelocity.y()) {
            velocity = newVelocity;   // a vector is a value: where nothing was clamped or zeroed, keep the one given
        }
    }

    /** Speeds squared below this are within {@link Arena#MAX_SPEED} beyond doubt: far more than rounding under it. */
    private static final double CLEARLY_WITHIN_LIMIT = Arena.MAX_SPEED * Arena.MAX_SPEED * (1 - 1e-9);

    /** As {@link #setVelocity(Vect)} with {@code new Vect(newX, newY)}, without making it. */
    void setVelocity(double newX, double newY) {
        double x0 = newX + 0.0;
        double y0 = newY + 0.0;
        // The length (a hypot) only where the squares leave the limit in doubt: they lie within a few ulps of it.
        if (x0 * x0 + y0 * y0 > CLEARLY_WITHIN_LIMIT && Components.length(x0, y0) > Arena.MAX_SPEED * (1 + 1e-12)) {
            double factor = Arena.MAX_SPEED / Components.length(x0, y0);   // Vect.times
            x0 = x0 * factor + 0.0;
            y0 = y0 * factor + 0.0;
        }
        double newVx = negligibleToZero(x0);
        double newVy = negligibleToZero(y0);
        if (newVx != vx || newVy != vy) {
            vx = newVx;
            vy = newVy;
            motionChanged();
            // its vector is made when asked for, but for a ball stopped (one at rest on its contacts) or unchanged
            velocity = newVx == 0 && newVy == 0 ? Vect.ZERO : null;
        }
    }

    private void keepVelocity(Vect v) {
        vx = v.x();
        vy = v.y();
        velocity = v;
        motionChanged();
    }

    private static double negligibleToZero(double component) {
        return Math.abs(component) < Tolerances.NEGLIGIBLE_SPEED ? 0 : component;
    }

    /**
     * Straight on for {@code dt} seconds: the centre {@code new Vect(x + vx dt, y + vy dt)} would give. A ball that
     * stays where it is (at rest, as a ball lying on its contacts mostly is) keeps its vector and circle.
     */
    void advance(double dt) {
        if (filed) {
            motions.x[slot] = motions.x[slot] + vx * dt + 0.0;
            motions.y[slot] = motions.y[slot] + vy * dt + 0.0;
        } else {
            x = x + vx * dt + 0.0;
            y = y + vy * dt + 0.0;
        }
    }

    /** An absorber holds it there, at rest, its contacts forgotten. For the board, not for views. */
    public void capture(Vect holdingPosition) {
        disturb();
        captured = true;
        moveTo(holdingPosition);
        keepVelocity(Vect.ZERO);
    }

    /** Free again, at that place and velocity, its contacts forgotten. For the board, not for views. */
    public void release(Vect launchPosition, Vect launchVelocity) {
        disturb();
        captured = false;
        moveTo(launchPosition);
        setVelocity(launchVelocity);
        motionChanged();   // free again: its slot moves, whether or not the velocity changed
    }

    @Override
    public String toString() {
        return "ball " + name + " at " + position() + " moving " + velocity() + (captured ? " (captured)" : "")
                + (asleep ? " (asleep)" : "");
    }
}
