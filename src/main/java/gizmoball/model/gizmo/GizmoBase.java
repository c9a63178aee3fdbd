package gizmoball.model.gizmo;

import java.util.List;
import java.util.Optional;
import java.util.function.Function;

import physics.Vect;

/**
 * What every gizmo holds: name, kind, footprint cell, rotation, last trigger time, and its physical shape, which is
 * rebuilt only when the gizmo is placed, moved or rotated (never per tick). Views see a gizmo as a {@link Gizmo}.
 * The members the board and its loop need beyond that are public only because the board lives in another
 * package; each says so: only the board changes gizmos, after it has checked the change on a copy.
 */
public abstract sealed class GizmoBase permits Bumper, TurningBar, PolygonGizmo, Accelerator, SwitchedCell {
    private final String name;
    private final GizmoKind kind;
    /** Its kind's, kept here: the loop's hot paths ask it of every gizmo near a ball. */
    private final BallTaking ballTaking;
    private int x;
    private int y;
    private int rotation;
    private double lastTriggeredAt = Double.NEGATIVE_INFINITY;
    private Shape shape;
    private Rgb colour;

    GizmoBase(String name, GizmoKind kind, int x, int y) {
        this.name = name;
        this.kind = kind;
        this.ballTaking = kind.ballTaking();
        this.x = x;
        this.y = y;
    }

    /** Copies the common state of another gizmo (for deep copies). */
    GizmoBase(GizmoBase other) {
        this(other.name, other.kind, other.x, other.y);
        this.rotation = other.rotation;
        this.lastTriggeredAt = other.lastTriggeredAt;
        this.shape = other.shape;
        this.colour = other.colour;
    }

    public String name() {
        return name;
    }

    public GizmoKind kind() {
        return kind;
    }

    public int x() {
        return x;
    }

    public int y() {
        return y;
    }

    public int width() {
        return kind.width();
    }

    public int height() {
        return kind.height();
    }

    public int rotation() {
        return rotation;
    }

    public double lastTriggeredAt() {
        return lastTriggeredAt;
    }

    public abstract double reflectionCoefficient();

    public Optional<Rgb> colour() {
        return Optional.ofNullable(colour);
    }

    /** What it does with a ball that touches it ({@link GizmoKind#ballTaking}). For the board and its loop. */
    public final BallTaking ballTaking() {
        return ballTaking;
    }

    /**
     * Whether a ball that touches it is taken (captured, sunk) rather than bounced: what touches it is never a
     * contact. The loop asks this, not which kinds take balls. Final and a field's read, so that the hot loops that
     * ask it pay no call through every kind.
     */
    public final boolean takesBalls() {
        return ballTaking != BallTaking.NONE;
    }

    /**
     * Takes the ball named {@code ball}, of radius {@code ballRadius}, that touched it, if it {@link #takesBalls}:
     * where the ball stops (an absorber holds it at its corner behind those it already holds, a sink at its centre).
     * For the board, not for views.
     */
    public Vect take(String ball, double ballRadius) {
        throw new IllegalStateException(this + " takes no balls");
    }

    /**
     * Whether a ball that bounces off it leaves at another speed than the bounce's own ({@link #boost}): an
     * accelerator's. For the loop.
     */
    public boolean boosts() {
        return false;
    }

    /**
     * The velocity of a ball leaving it after bouncing at {@code bounced}, at most {@code maxSpeed} fast: the bounce's
     * own but where it {@link #boosts}. For the loop.
     */
    public Vect boost(Vect bounced, double maxSpeed) {
        return bounced;
    }

    /** Most kinds hold no balls; one that {@link BallTaking#HOLDS} them says which. */
    public List<String> held() {
        return List.of();
    }

    /**
     * It no longer holds the ball named {@code ball} (fired, moved or deleted), if it did. For the board and its loop,
     * not for views.
     */
    public void letGo(String ball) {
    }

    /** Most kinds are no plunger; an absorber may be one ({@link Setting.Pull}). */
    public Optional<Plunger> plunger() {
        return Optional.empty();
    }

    /** No plunger, never pulled. */
    public double pull() {
        return 0;
    }

    /** Most kinds have no bar that a key swings; a flipper says where its bar goes. */
    public Optional<Sweep> sweep() {
        return Optional.empty();
    }

    /** Play changes nothing of most kinds that a save must write; a kind it changes says what. */
    public PlayState playState() {
        return new PlayState.AsBuilt();
    }

    /**
     * Whether play can leave it as {@code state} says, so that a board saved during play can put it back so: a flipper
     * swung, a spinner turned. For the board, not for views.
     */
    public boolean canBe(PlayState state) {
        return false;
    }

    /** Why it cannot be put back as {@code state} says though it {@link #canBe} so (out of its range), or empty. */
    public Optional<String> restoreProblem(PlayState state) {
        return Optional.empty();
    }

    /** Puts it as {@code state} says (it {@link #canBe} so, with no problem): its shape too. For the board. */
    public void restore(PlayState state) {
    }

    /** Most kinds hold nothing beyond their place, turn and colour; a kind that does says what. */
    public Setting setting() {
        return new Setting.None();
    }

    /**
     * Takes a setting of the record its {@link #setting} is (the board has checked it); {@code gizmos} finds the
     * board's others by name, for a setting that changes them too. For the board, not for views.
     */
    public void hold(Setting setting, Function<String, GizmoBase> gizmos) {
    }

    /** Its own colour, or empty for the kind's. For the board and its loop, not for views. */
    public void setColour(Optional<Rgb> newColour) {
        colour = newColour.orElse(null);
    }

    /**
     * The shape the collision detection uses now (for a flipper: at its current angle). For the board and its loop, not
     * for views.
     */
    public Shape shape() {
        return shape;
    }

    /** Builds the static shape for the current footprint and rotation; called after every placement change. */
    abstract Shape buildShape();

    /** Its 1x1 footprint cell's corners, clockwise on the screen from the top-left. */
    final List<Vect> cellOutline() {
        return List.of(new Vect(x, y), new Vect(x + 1, y), new Vect(x + 1, y + 1), new Vect(x, y + 1));
    }

    /**
     * Signed distance from p to the solid body of the gizmo as it is now (negative inside). For the board and its loop,
     * not for views.
     */
    public abstract double signedDistance(Vect p);

    /**
     * A deep copy with all play state (the board checks each change on one first). For the board and its loop, not for
     * views.
     */
    public abstract GizmoBase copy();

    /**
     * Puts its top-left cell at (newX, newY) and rebuilds its shape there. For the board and its loop, not for views.
     */
    public void moveTo(int newX, int newY) {
        x = newX;
        y = newY;
        rebuildShape();
    }

    /**
     * A quarter turn clockwise, if its kind {@link GizmoKind#rotates}, and its shape rebuilt. For the board and its loop, not for
     * views.
     */
    public void rotateClockwise() {
        if (kind.rotates()) {
            rotation = (rotation + 1) % 4;
            rebuildShape();
        }
    }

    final void rebuildShape() {
        shape = buildShape();
    }

    /** Records board time {@code time} as its last trigger or hit. For the board and its loop, not for views. */
    public void markTriggered(double time) {
        lastTriggeredAt = time;
    }

    /**
     * Performs one of its kind's {@link GizmoKind#actions} (the board has checked it is one), done through
     * {@code around} where it reaches beyond the gizmo: its press action as a key's press drives it, its release
     * action as a release does, its default as a trigger does; a flash is only the time the board records. For the
     * board and its loop, not for views.
     */
    public void perform(Action action, Surroundings around) {
        if (action == kind.pressAction()) {
            keyDown(around);
        } else if (action == kind.releaseAction()) {
            keyUp(around);
        } else if (action == kind.defaultAction()) {
            act(around);
        }
    }

    /**
     * Its action when it is triggered (by a hit on a source it is connected to, or a key's change binding), done
     * through {@code around} where it reaches beyond the gizmo. A bumper has none: it only records the time.
     * For the board and its loop, not for views.
     */
    public void act(Surroundings around) {
    }

    /**
     * Whether the player works it by a key (a flipper, a plunger): a tilted game makes it dead to its keys. For the
     * board, not for views.
     */
    public boolean workedByPlayer() {
        return false;
    }

    /**
     * The game tilted: it gives up what the player was doing with it (a flipper falls back to rest, a plunger lets go
     * of its pull without firing); most kinds do nothing. For the board, not for views.
     */
    public void tilt(Surroundings around) {
    }

    /** A key bound to its press went down: by default its action. For the board and its loop, not for views. */
    public void keyDown(Surroundings around) {
        act(around);
    }

    /** A key bound to its release went up: by default its action. For the board and its loop, not for views. */
    public void keyUp(Surroundings around) {
        act(around);
    }

    /**
     * Turns a point given for the unrotated footprint by the gizmo's rotation, clockwise about the footprint centre.
     */
    Vect rotated(double px, double py) {
        double cx = x + width() / 2.0;
        double cy = y + height() / 2.0;
        double dx = px - cx;
        double dy = py - cy;
        for (int i = 0; i < rotation; i++) {
            double turned = -dy;   // clockwise on screen (y down): (dx, dy) -> (-dy, dx)
            dy = dx;
            dx = turned;
        }
        return new Vect(cx + dx, cy + dy);
    }

    @Override
    public String toString() {
        return kind + " " + name + " at (" + x + "," + y + ")";
    }
}
