package gizmoball.model.gizmo;

import java.util.List;
import java.util.Optional;

import physics.Angle;
import physics.Circle;
import physics.Geometry;
import physics.LineSegment;
import physics.Vect;

/**
 * A left or right flipper: a 2 L bar with round ends of radius 0.25 pivoting near a top corner of its 2x2 box. It
 * swings between rest (0 degrees, hanging down) and active (90 degrees, lying along the top edge) at 1080 deg/s
 * and stops exactly at either limit. Its shape is two side segments and two end circles. The shapes at both stops
 * are built once per placement, so a flipper at a stop is as static as a bumper; only a swinging flipper builds
 * the shape of its current angle.
 */
public final class Flipper extends TurningBar implements FlipperView {
    /** Degrees from rest to the active stop. */
    public static final double MAX_ANGLE = 90;
    static final double DEGREES_PER_SECOND = 1080;
    /** Index of the pivot circle in {@link Shape#circles()}: it turns in place, so the loop treats it as still. */
    static final int PIVOT_CIRCLE = 0;
    /** Index of the tip circle in {@link Shape#circles()}. */
    static final int TIP_CIRCLE = 1;
    private static final double LIMIT_SNAP_DEGREES = 1e-9;

    private double angle;
    private boolean active;
    private Shape restShape;
    private Shape activeShape;

    Flipper(GizmoKind kind, String name, int x, int y) {
        super(name, kind, x, y);
        if (kind != GizmoKind.LEFT_FLIPPER && kind != GizmoKind.RIGHT_FLIPPER) {
            throw new IllegalArgumentException(kind.withArticle() + " is not a flipper");
        }
        rebuildShape();
    }

    private Flipper(Flipper other) {
        super(other);
        this.angle = other.angle;
        this.active = other.active;
        this.restShape = other.restShape;
        this.activeShape = other.activeShape;
    }

    /** Centre of the round end at the pivot: the rest shape's, made once per placement (the loop asks it often). */
    @Override
    public Vect pivot() {
        return restShape.circles().get(PIVOT_CIRCLE).getCenter();
    }

    /** Where its placement puts the pivot. */
    private Vect placedPivot() {
        double local = kind() == GizmoKind.LEFT_FLIPPER ? x() + RADIUS : x() + 2 - RADIUS;
        return rotated(local, y() + RADIUS);
    }

    /** Centre of the other round end, at the current angle. */
    public Vect tip() {
        return shape().circles().get(TIP_CIRCLE).getCenter();
    }

    /** From its bar at rest a quarter turn up: anticlockwise on the screen for a left flipper, clockwise for a right one. */
    @Override
    public Optional<Sweep> sweep() {
        // At rest a flipper of rotation 0 hangs straight down; each quarter turn turns it clockwise on the screen
        // (y grows downward, so clockwise takes (x, y) to (-y, x)).
        double x = 0;
        double y = 1;
        for (int turn = 0; turn < rotation(); turn++) {
            double turned = -y;
            y = x;
            x = turned;
        }
        Vect up = kind() == GizmoKind.LEFT_FLIPPER ? new Vect(y, -x) : new Vect(-y, x);
        Vect pivot = pivot();
        return Optional.of(new Sweep(pivot, new Vect(x, y), up, tip().minus(pivot).length() + RADIUS));
    }

    /** Degrees swung from rest, 0..90. */
    public double angleFromRest() {
        return angle;
    }

    /** True while the flipper is up or swinging up. */
    public boolean isActive() {
        return active;
    }

    /** Swung where play moved it from rest (away from it, or on its way up); at rest and down, as built. */
    @Override
    public PlayState playState() {
        return angle != 0 || active ? new PlayState.Swung(angle, active) : new PlayState.AsBuilt();
    }

    /** Short of the stop it swings to. */
    @Override
    boolean turns() {
        return active ? angle < MAX_ANGLE : angle > 0;
    }

    private void activate() {
        if (!active) {
            toggle();
        }
    }

    private void deactivate() {
        if (active) {
            toggle();
        }
    }

    /** Sent the other way: whatever stalled it is behind it now. */
    private void toggle() {
        active = !active;
        release();
    }

    /** Triggered, it toggles: up if it was down or going down, else back down. */
    @Override
    public void act(Surroundings around) {
        boolean wasMoving = isMoving();
        toggle();
        swung(wasMoving, around);
    }

    /** A key swings it up while held: up when the key goes down, whichever way it was going. */
    @Override
    public void keyDown(Surroundings around) {
        boolean wasMoving = isMoving();
        activate();
        swung(wasMoving, around);
    }

    /** Driven ({@code wasMoving}: whether it was swinging before): one that starts to swing is heard and wakes its box. */
    private void swung(boolean wasMoving, Surroundings around) {
        if (isMoving() && !wasMoving) {
            around.swingStarted(name(), active);
            around.startedMoving(this);
        }
    }

    /** The player's own: a tilt leaves it dead. */
    @Override
    public boolean workedByPlayer() {
        return true;
    }

    /** A tilt lowers it, as its release does. */
    @Override
    public void tilt(Surroundings around) {
        perform(Action.LOWER, around);
    }

    /** Back down when the held key goes up, whichever way it was going. */
    @Override
    public void keyUp(Surroundings around) {
        boolean wasMoving = isMoving();
        deactivate();
        swung(wasMoving, around);
    }

    /** Play swings it. */
    @Override
    public boolean canBe(PlayState state) {
        return state instanceof PlayState.Swung;
    }

    @Override
    public Optional<String> restoreProblem(PlayState state) {
        double degrees = ((PlayState.Swung) state).degrees();
        return degrees >= 0 && degrees <= MAX_ANGLE ? Optional.empty()
                : Optional.of("flipper " + name() + ": angle " + degrees + " must be from 0 to " + MAX_ANGLE + " degrees");
    }

    @Override
    public void restore(PlayState state) {
        PlayState.Swung swung = (PlayState.Swung) state;
        setState(swung.degrees(), swung.up());
    }

    /**
     * Puts the flipper at an angle (0..90 degrees from rest), swinging toward its active stop or its rest. For the
     * board and its loop, not for views.
     */
    public void setState(double degrees, boolean toActive) {
        angle = degrees;
        active = toActive;
        release();
        reshaped();
    }

    /**
     * Seconds until the flipper reaches the limit it is swinging to (0 when still). For the board and its loop, not for
     * views.
     */
    @Override
    public double timeToStop() {
        return (active ? MAX_ANGLE - angle : angle) / DEGREES_PER_SECOND;
    }

    /**
     * Signed angular velocity in radians per second in the library's sense (+x toward +y), 0 when still. A left flipper
     * swings up from +y (hanging) to +x (the top edge): toward -; the right one mirrors it. For the board and its loop,
     * not for views.
     */
    @Override
    public double angularVelocity() {
        if (!isMoving()) {
            return 0;
        }
        double up = kind() == GizmoKind.LEFT_FLIPPER ? -1 : 1;
        return (active ? up : -up) * Math.toRadians(DEGREES_PER_SECOND);
    }

    /** Swings toward the current limit, stopping exactly at it. */
    @Override
    void turn(double dt) {
        double step = DEGREES_PER_SECOND * dt;
        double limit = active ? MAX_ANGLE : 0;
        double next = active ? Math.min(MAX_ANGLE, angle + step) : Math.max(0, angle - step);
        // Sums of sub-tick steps round; a swing that ends within rounding of its limit ends exactly at it.
        angle = Math.abs(limit - next) < LIMIT_SNAP_DEGREES ? limit : next;
    }

    /** The shape at the limit it is swinging to (where it will stop). For the board and its loop, not for views. */
    @Override
    public Shape shapeAtStop() {
        return shapeAt(active ? MAX_ANGLE : 0);
    }

    @Override
    public boolean turnsInPlace(int index) {
        return index == PIVOT_CIRCLE;
    }

    @Override
    Shape shapeNow() {
        return shapeAt(angle);
    }

    @Override
    Shape buildShape() {
        Vect pivot = placedPivot();
        Vect restTip = pivot.plus(rotated(0, 1).minus(rotated(0, 0)).times(2 - 2 * RADIUS));
        Vect across = rotated(1, 0).minus(rotated(0, 0)).times(RADIUS);
        restShape = new Shape(
                List.of(new LineSegment(pivot.plus(across), restTip.plus(across)),
                        new LineSegment(pivot.minus(across), restTip.minus(across))),
                List.of(new Circle(pivot, RADIUS), new Circle(restTip, RADIUS)));
        activeShape = turned(MAX_ANGLE);
        reshaped();
        return restShape;
    }

    /** The rest shape turned about the pivot by the given degrees toward the active position. */
    private Shape shapeAt(double degrees) {
        if (degrees == 0) {
            return restShape;
        }
        return degrees == MAX_ANGLE ? activeShape : turned(degrees);
    }

    private Shape turned(double degrees) {
        double up = kind() == GizmoKind.LEFT_FLIPPER ? -1 : 1;
        Angle turn = new Angle(up * Math.toRadians(degrees));
        Vect pivot = restShape.circles().get(PIVOT_CIRCLE).getCenter();
        // Its two sides and two round ends (buildShape), each turned, straight into the shape's lists: a swinging
        // flipper turns its shape at every tick.
        List<LineSegment> sides = restShape.segments();
        List<Circle> ends = restShape.circles();
        return new Shape(
                List.of(Geometry.rotateAround(sides.get(0), pivot, turn),
                        Geometry.rotateAround(sides.get(1), pivot, turn)),
                List.of(Geometry.rotateAround(ends.get(0), pivot, turn),
                        Geometry.rotateAround(ends.get(1), pivot, turn)));
    }

    @Override
    public Flipper copy() {
        return new Flipper(this);
    }
}
