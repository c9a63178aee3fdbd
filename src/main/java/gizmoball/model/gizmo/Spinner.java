package gizmoball.model.gizmo;

import java.util.List;
import java.util.Optional;
import java.util.function.Function;

import physics.Circle;
import physics.LineSegment;
import physics.Vect;

/**
 * A 2x2 bar with round ends of radius 0.25 turning without end about the centre of its box, at the speed its author
 * gives it (one turn a second unless set), either way. The bar is 2 L long, ends included: its ends' centres lie
 * 0.75 L from the pivot, so at every angle the whole bar stays within the disc of radius 1 inscribed in its box.
 * Its shape is two side segments and two end circles; neither end is at the pivot, so neither turns in place. The
 * angle is kept reduced to [0, 2 pi) and the shape built from it with StrictMath, so play is the same everywhere.
 */
public final class Spinner extends TurningBar implements SpinnerView {
    /** From the pivot to each end's centre: the end's outer edge touches the inscribed disc. */
    static final double ARM = 1 - RADIUS;
    private static final double TWO_PI = 2 * Math.PI;

    /** Signed, turns per second: positive turns +x toward +y (clockwise on the screen, y down). */
    private double turnsPerSecond = Setting.Speed.DEFAULT;
    /** The bar's direction from +x toward +y, in [0, 2 pi). */
    private double angle;
    /** Turning unless told to stop; stopped, it holds its angle. */
    private boolean running = true;

    Spinner(String name, int x, int y) {
        super(name, GizmoKind.SPINNER, x, y);
        rebuildShape();
    }

    private Spinner(Spinner other) {
        super(other);
        this.turnsPerSecond = other.turnsPerSecond;
        this.angle = other.angle;
        this.running = other.running;
    }

    @Override
    public double turnsPerSecond() {
        return turnsPerSecond;
    }

    @Override
    public Setting setting() {
        return new Setting.Speed(turnsPerSecond);
    }

    @Override
    public void hold(Setting setting, Function<String, GizmoBase> gizmos) {
        turnsPerSecond = ((Setting.Speed) setting).turnsPerSecond();
    }

    /** Play turns it and stops it. */
    @Override
    public boolean canBe(PlayState state) {
        return state instanceof PlayState.Turned;
    }

    @Override
    public Optional<String> restoreProblem(PlayState state) {
        double radians = ((PlayState.Turned) state).radians();
        return Double.isFinite(radians) ? Optional.empty()
                : Optional.of("spinner " + name() + ": angle " + radians + " is not a finite number");
    }

    @Override
    public void restore(PlayState state) {
        PlayState.Turned turned = (PlayState.Turned) state;
        setAngle(turned.radians());
        setRunning(turned.running());
    }

    /** Puts the bar at an angle (reduced to [0, 2 pi)). For the board and its loop, not for views. */
    public void setAngle(double radians) {
        angle = reduced(radians);
        reshaped();
    }

    /** Lets it turn or holds it still. For the board and its loop, not for views. */
    public void setRunning(boolean turning) {
        running = turning;
    }

    @Override
    public double angle() {
        return angle;
    }

    @Override
    public boolean isRunning() {
        return running;
    }

    /** Turned where play moved it from its start or stopped it; at its start and running, as built. */
    @Override
    public PlayState playState() {
        return angle != 0 || !running ? new PlayState.Turned(angle, running) : new PlayState.AsBuilt();
    }

    @Override
    public Vect pivot() {
        return new Vect(x() + 1, y() + 1);
    }

    @Override
    public List<Vect> ends() {
        Shape now = shape();
        return List.of(now.circles().get(0).getCenter(), now.circles().get(1).getCenter());
    }

    /** The end its angle points to. */
    @Override
    public Vect tip() {
        return shape().circles().get(1).getCenter();
    }

    /** Running. */
    @Override
    boolean turns() {
        return running;
    }

    /** In the library's sense (+x toward +y), radians per second; 0 while stopped or stalled. */
    @Override
    public double angularVelocity() {
        return isMoving() ? TWO_PI * turnsPerSecond : 0;
    }

    /** Never, while it turns; 0 while it is stopped or stalled, so that the loop takes its shape as still. */
    @Override
    public double timeToStop() {
        return isMoving() ? Double.POSITIVE_INFINITY : 0;
    }

    /** The shape now: the loop asks it only while the spinner is still. */
    @Override
    public Shape shapeAtStop() {
        return shape();
    }

    @Override
    public boolean turnsInPlace(int index) {
        return false;
    }

    @Override
    void turn(double dt) {
        angle = reduced(angle + angularVelocity() * dt);
    }

    /** The angle in [0, 2 pi); a sum within rounding below 0 lands on 2 pi and is taken as 0. */
    private static double reduced(double radians) {
        double turned = radians - TWO_PI * Math.floor(radians / TWO_PI);
        return turned >= TWO_PI ? 0 : turned;
    }

    /**
     * Reverses (and goes on, whatever stalled it being behind it now), starts or stops it; told to start, it wakes
     * what sleeps in its box. A flash only lights it.
     */
    @Override
    public void perform(Action action, Surroundings around) {
        boolean wasMoving = isMoving();
        switch (action) {
            case REVERSE -> {
                turnsPerSecond = -turnsPerSecond;
                release();
            }
            case START -> running = true;
            case STOP -> running = false;
            default -> {
            }
        }
        if (isMoving() && !wasMoving) {
            around.startedMoving(this);
        }
    }

    @Override
    Shape shapeNow() {
        return shapeAt(angle);
    }

    @Override
    Shape buildShape() {
        reshaped();
        return shape();
    }

    /** The bar at an angle: its ends' centres ARM either side of the pivot, its sides RADIUS either side of them. */
    private Shape shapeAt(double radians) {
        Vect pivot = pivot();
        Vect along = new Vect(StrictMath.cos(radians), StrictMath.sin(radians));
        Vect arm = along.times(ARM);
        Vect across = new Vect(-along.y(), along.x()).times(RADIUS);
        Vect back = pivot.minus(arm);
        Vect front = pivot.plus(arm);
        return new Shape(
                List.of(new LineSegment(back.plus(across), front.plus(across)),
                        new LineSegment(back.minus(across), front.minus(across))),
                List.of(new Circle(back, RADIUS), new Circle(front, RADIUS)));
    }

    @Override
    public Spinner copy() {
        return new Spinner(this);
    }
}
