package gizmoball.model.gizmo;

import java.util.List;
import java.util.Optional;
import java.util.function.UnaryOperator;

/**
 * What a gizmo of a kind holds beyond its place, size, turn and colour: the one value its author sets on it (an
 * accelerator's factor, a spawner's velocity, an absorber's plunger, a spinner's speed, a portal's pair), or {@link None}. It is read from
 * the gizmo ({@link Gizmo#setting}) and written through the board's one operation ({@code Board.set}), which takes
 * it only for a gizmo that holds a setting of the same record and only if {@link #problem} finds none. So a file's
 * lines, copy and paste, the properties panel and undo carry any kind's setting alike; docs/design.md, "A kind's
 * setting", says how to add one.
 */
public sealed interface Setting {
    /** What a setting's check may ask of the board it is given on. */
    interface Board {
        /** The gizmo of that name (the board refuses, naming it, if it has none). */
        Gizmo gizmo(String name);

        /** The board's speed limit in L/s. */
        double maxSpeed();
    }

    /** Why a gizmo holding another record refuses this one, before ": NAME is a KIND": "only a spinner has ...". */
    String onlyFor();

    /** Why gizmo {@code name} of {@code board} cannot take this value; empty if it can. */
    Optional<String> problem(String name, Board board);

    /** What a new gizmo of its kind holds: a board file leaves it out. */
    boolean isDefault();

    /** What it makes gizmo {@code name} do, in words: an edit's name in the history. */
    String said(String name);

    /** The other gizmos it names: it is copied only with them (after them) and renamed as they are. */
    default List<String> names() {
        return List.of();
    }

    /** The same setting naming the gizmos {@code rename} gives for the ones it names. */
    default Setting renamed(UnaryOperator<String> rename) {
        return this;
    }

    /** A kind with no value of its own. */
    record None() implements Setting {
        public String onlyFor() {
            return "only a gizmo without a value of its own holds none";
        }

        public Optional<String> problem(String name, Board board) {
            return Optional.empty();
        }

        public boolean isDefault() {
            return true;
        }

        public String said(String name) {
            return name + " holds nothing of its own";
        }
    }

    /** An accelerator's: how many times faster it sends a ball away, 1 to {@link #MAX}. */
    record Factor(double factor) implements Setting {
        /** The factor of an accelerator the author has not given one. */
        public static final double DEFAULT = 1.5;
        /** The largest factor: a ball at 10 L/s leaves at the speed limit after two hits. */
        public static final double MAX = 5;

        public String onlyFor() {
            return "only an accelerator has a factor";
        }

        public Optional<String> problem(String name, Board board) {
            return factor >= 1 && factor <= MAX ? Optional.empty()
                    : Optional.of("an accelerator's factor is 1 to " + (int) MAX + ", not " + factor);
        }

        public boolean isDefault() {
            return factor == DEFAULT;
        }

        public String said(String name) {
            return name + " speeds balls up " + factor + " times";
        }
    }

    /** A spawner's: the velocity, in L/s, of the balls it adds; finite and at most the board's speed limit. */
    record Launch(double vx, double vy) implements Setting {
        public String onlyFor() {
            return "only a spawner has a velocity for its balls";
        }

        public Optional<String> problem(String name, Board board) {
            return Double.isFinite(vx) && Double.isFinite(vy) && StrictMath.hypot(vx, vy) <= board.maxSpeed()
                    ? Optional.empty()
                    : Optional.of("a spawner's velocity is finite and at most " + (int) board.maxSpeed()
                            + " L/s fast, not (" + vx + ", " + vy + ")");
        }

        public boolean isDefault() {
            return vx == 0 && vy == 0;
        }

        public String said(String name) {
            return name + " spawns balls at (" + vx + ", " + vy + ") L/s";
        }
    }

    /** An absorber's: the {@link Plunger} it is, or empty for one that fires at once. */
    record Pull(Optional<Plunger> plunger) implements Setting {
        public String onlyFor() {
            return "only an absorber can be a plunger";
        }

        public Optional<String> problem(String name, Board board) {
            if (plunger.isEmpty()) {
                return Optional.empty();
            }
            double speed = plunger.get().fullSpeed();
            double seconds = plunger.get().pullSeconds();
            if (!(speed > Plunger.MIN_SPEED && speed <= board.maxSpeed())) {
                return Optional.of("a plunger's full pull launches faster than " + (int) Plunger.MIN_SPEED
                        + " L/s and at most " + (int) board.maxSpeed() + " L/s, not " + speed);
            }
            if (!(seconds >= Plunger.MIN_PULL_SECONDS && seconds <= Plunger.MAX_PULL_SECONDS)) {
                return Optional.of("a plunger's full pull takes " + Plunger.MIN_PULL_SECONDS + " to "
                        + (int) Plunger.MAX_PULL_SECONDS + " seconds, not " + seconds);
            }
            return Optional.empty();
        }

        public boolean isDefault() {
            return plunger.isEmpty();
        }

        public String said(String name) {
            return plunger.map(p -> name + " is a plunger: a full pull launches at " + p.fullSpeed() + " L/s after "
                    + p.pullSeconds() + " s").orElse(name + " fires at once");
        }
    }

    /**
     * A spinner's: its speed and way in turns per second, positive clockwise on the screen, nonzero and at most
     * {@link #MAX} either way.
     */
    record Speed(double turnsPerSecond) implements Setting {
        /** The speed of a spinner its author has not given one, in turns per second (clockwise on the screen). */
        public static final double DEFAULT = 1;
        /** The fastest either way, in turns per second: a flipper's 1080 deg/s. */
        public static final double MAX = 3;

        public String onlyFor() {
            return "only a spinner has a speed of its own";
        }

        public Optional<String> problem(String name, Board board) {
            return turnsPerSecond != 0 && Math.abs(turnsPerSecond) <= MAX ? Optional.empty()
                    : Optional.of("a spinner turns up to " + (int) MAX
                            + " times a second either way (not 0: stop it instead), not " + turnsPerSecond);
        }

        public boolean isDefault() {
            return turnsPerSecond == DEFAULT;
        }

        public String said(String name) {
            return name + " turns " + Math.abs(turnsPerSecond) + " times a second "
                    + (turnsPerSecond > 0 ? "clockwise" : "anticlockwise");
        }
    }

    /**
     * A portal's: the portal a ball entering its mouth leaves by, or empty for none (a wall). Given, it pairs both:
     * each leaves the pair it had, whose other portal is left without one.
     */
    record Pair(Optional<String> portal) implements Setting {
        /** Paired with {@code other}, or with an empty name with none. */
        public static Pair with(String other) {
            return new Pair(other.isEmpty() ? Optional.empty() : Optional.of(other));
        }

        public String onlyFor() {
            return "only portals are paired";
        }

        public Optional<String> problem(String name, Board board) {
            if (portal.isEmpty()) {
                return Optional.empty();
            }
            Gizmo other = board.gizmo(portal.get());
            if (!(other.setting() instanceof Pair)) {   // what can be paired holds a pair: a portal
                return Optional.of(onlyFor() + ": " + other.name() + " is " + other.kind().withArticle());
            }
            return other.name().equals(name) ? Optional.of("a portal cannot be paired with itself: " + name)
                    : Optional.empty();
        }

        public boolean isDefault() {
            return portal.isEmpty();
        }

        public String said(String name) {
            return portal.map(other -> name + " and " + other + " are a pair of portals")
                    .orElse(name + " has no pair: a wall");
        }

        @Override
        public List<String> names() {
            return portal.stream().toList();
        }

        @Override
        public Setting renamed(UnaryOperator<String> rename) {
            return new Pair(portal.map(rename));
        }
    }
}
