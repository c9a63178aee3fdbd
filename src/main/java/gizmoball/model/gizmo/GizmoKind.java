package gizmoball.model.gizmo;

import java.util.List;
import java.util.Locale;

/**
 * The kinds of gizmo a board can hold, and the one home of what each kind is beyond its class: the footprint it
 * occupies (an absorber's size is per gizmo), the prefix of the names the editor gives it, what a hit on it scores
 * unless the board says, the class that plays it and the name the player sees.
 */
public enum GizmoKind {
    // The bumpers score, the more the harder they are to hit (an accelerator a little: it is easy to hit again; a
    // drop target most, hit once until it is raised again); flippers, absorbers and sinks, like the walls, score
    // nothing unless the board says (a sink scores when it takes a ball).
    SQUARE(1, "S", 10), CIRCLE(1, "C", 50), TRIANGLE(1, "T", 25), LEFT_FLIPPER(2, "LF", 0), RIGHT_FLIPPER(2, "RF", 0),
    ABSORBER(1, "A", 0), SINK(1, "SK", 0), ACCELERATOR(1, "AC", 20), SPAWNER(1, "SP", 0), GATE(1, "G", 0),
    DROP_TARGET(1, "DT", 100), PORTAL(1, "P", 0), SPINNER(2, "SN", 5);

    private final int side;
    private final String namePrefix;
    private final int defaultPoints;

    /**
     * @param side          its footprint's side in cells
     * @param namePrefix    what the names the editor gives it start with (S1, LF2), one of its own
     * @param defaultPoints what a real hit on it scores unless the board gives the gizmo its own
     */
    GizmoKind(int side, String namePrefix, int defaultPoints) {
        this.side = side;
        this.namePrefix = namePrefix;
        this.defaultPoints = defaultPoints;
    }

    /** What the names the editor gives gizmos of this kind start with, before a number: S1, C2, LF1. */
    public String namePrefix() {
        return namePrefix;
    }

    /** What a real hit on it scores unless the board gives the gizmo a value of its own. */
    public int defaultPoints() {
        return defaultPoints;
    }

    public int width() {
        return side;
    }

    public int height() {
        return side;
    }

    /**
     * Whether a quarter turn changes it: not for a circle or an absorber, which look and play the same turned. A switch
     * over every kind, so that a new kind says.
     */
    public boolean rotates() {
        return switch (this) {
            case SQUARE, TRIANGLE, LEFT_FLIPPER, RIGHT_FLIPPER, SPAWNER, PORTAL -> true;
            // A spinner turns through every angle anyway: a quarter turn of its start changes nothing of its play.
            case CIRCLE, ABSORBER, SINK, ACCELERATOR, GATE, DROP_TARGET, SPINNER -> false;
        };
    }

    /**
     * What a connection or a key binding can tell a gizmo of this kind to do, its default (what a hit on a source it
     * is connected to makes it do) first. A switch over every kind, so that a new kind says.
     */
    public List<Action> actions() {
        return switch (this) {
            case SQUARE, CIRCLE, TRIANGLE, SINK, ACCELERATOR, PORTAL -> List.of(Action.FLASH);
            case LEFT_FLIPPER, RIGHT_FLIPPER -> List.of(Action.TOGGLE, Action.RAISE, Action.LOWER, Action.FLASH);
            case ABSORBER -> List.of(Action.FIRE, Action.FLASH);
            case SPAWNER -> List.of(Action.SPAWN, Action.FLASH);
            case GATE -> List.of(Action.TOGGLE, Action.OPEN, Action.CLOSE, Action.FLASH);
            case DROP_TARGET -> List.of(Action.RAISE, Action.FLASH);
            case SPINNER -> List.of(Action.REVERSE, Action.START, Action.STOP, Action.FLASH);
        };
    }

    /** What it does when triggered unless a connection says otherwise: the first of its {@link #actions}. */
    public Action defaultAction() {
        return actions().get(0);
    }

    /**
     * What a key bound to its press makes it do unless the binding says: a flipper rises, a gate opens (so that a held
     * key holds either), others do their default.
     */
    public Action pressAction() {
        return switch (this) {
            case LEFT_FLIPPER, RIGHT_FLIPPER -> Action.RAISE;
            case GATE -> Action.OPEN;
            case SQUARE, CIRCLE, TRIANGLE, ABSORBER, SINK, ACCELERATOR, SPAWNER, DROP_TARGET, PORTAL, SPINNER ->
                    defaultAction();
        };
    }

    /** What a key bound to its release makes it do unless the binding says: a flipper falls, a gate closes, others their default. */
    public Action releaseAction() {
        return switch (this) {
            case LEFT_FLIPPER, RIGHT_FLIPPER -> Action.LOWER;
            case GATE -> Action.CLOSE;
            case SQUARE, CIRCLE, TRIANGLE, ABSORBER, SINK, ACCELERATOR, SPAWNER, DROP_TARGET, PORTAL, SPINNER ->
                    defaultAction();
        };
    }

    /**
     * Whether a gizmo of this kind can be a game's drain, its captured balls lost: an absorber (a switch over every
     * kind, so that a new kind says).
     */
    public boolean canDrain() {
        return switch (this) {
            case ABSORBER -> true;
            case SQUARE, CIRCLE, TRIANGLE, LEFT_FLIPPER, RIGHT_FLIPPER, SINK, ACCELERATOR, SPAWNER, GATE, DROP_TARGET,
                    PORTAL, SPINNER -> false;
        };
    }

    /**
     * What a gizmo of this kind does with a ball that touches it: an absorber holds it, a sink takes it out of play.
     * A switch over every kind, so that a new kind says.
     */
    public BallTaking ballTaking() {
        return switch (this) {
            case ABSORBER -> BallTaking.HOLDS;
            case SINK -> BallTaking.REMOVES;
            case SQUARE, CIRCLE, TRIANGLE, LEFT_FLIPPER, RIGHT_FLIPPER, ACCELERATOR, SPAWNER, GATE, DROP_TARGET, PORTAL,
                    SPINNER -> BallTaking.NONE;
        };
    }

    /**
     * Whether each gizmo of this kind has a size of its own, given by its corners (an absorber's; the board's
     * {@code addAbsorber}) and changed by dragging its edges, rather than the kind's {@link #width} and {@link #height}.
     * A switch over every kind, so that a new kind says.
     */
    public boolean sizedByCorners() {
        return switch (this) {
            case ABSORBER -> true;
            case SQUARE, CIRCLE, TRIANGLE, LEFT_FLIPPER, RIGHT_FLIPPER, SINK, ACCELERATOR, SPAWNER, GATE, DROP_TARGET,
                    PORTAL, SPINNER -> false;
        };
    }

    /**
     * A new gizmo of a kind {@link #sizedByCorners} with its top-left cell at (x, y), {@code width} by {@code height}
     * cells. For the board, not for views.
     */
    public GizmoBase createSized(String name, int x, int y, int width, int height) {
        return switch (this) {
            case ABSORBER -> new Absorber(name, x, y, width, height);
            case SQUARE, CIRCLE, TRIANGLE, LEFT_FLIPPER, RIGHT_FLIPPER, SINK, ACCELERATOR, SPAWNER, GATE, DROP_TARGET,
                    PORTAL, SPINNER -> throw new IllegalArgumentException(withArticle() + " has its kind's size");
        };
    }

    /** How every message and help text names the kind: "square", "left flipper". */
    public String displayName() {
        return name().toLowerCase(Locale.ROOT).replace('_', ' ');
    }

    /** The name with its article: "a square", "an absorber". */
    public String withArticle() {
        String name = displayName();
        return ("aeiou".indexOf(name.charAt(0)) >= 0 ? "an " : "a ") + name;
    }

    /**
     * A new gizmo of this kind with its top-left cell at (x, y): the one place that maps a kind to its class. An
     * absorber has a size of its own and is made from its corners (the board's {@code addAbsorber}). For the board and
     * its loop, not for views.
     */
    public GizmoBase create(String name, int x, int y) {
        return switch (this) {
            case SQUARE, CIRCLE, TRIANGLE -> new Bumper(this, name, x, y);
            case LEFT_FLIPPER, RIGHT_FLIPPER -> new Flipper(this, name, x, y);
            case ABSORBER -> throw new IllegalArgumentException("an absorber is made from its corners, not a cell");
            case SINK -> new Sink(name, x, y);
            case ACCELERATOR -> new Accelerator(name, x, y);
            case SPAWNER -> new Spawner(name, x, y);
            case GATE -> new Gate(name, x, y);
            case DROP_TARGET -> new DropTarget(name, x, y);
            case PORTAL -> new Portal(name, x, y);
            case SPINNER -> new Spinner(name, x, y);
        };
    }
}
