package gizmoball.fuzz;

/**
 * One broken rule of play found after one tick.
 *
 * @param tick   the tick just played (ticks counted from 1 at load; 0 is the board as loaded)
 * @param ball   the ball concerned (for a gain of energy: the board's whole kinetic energy, named "all")
 * @param amount how much: depth in L for an overlap, L outside the board for an escape, the relative gain for energy,
 *               the speed in L/s of a frozen ball, the gap in L of a hovering ball to the nearest thing
 * @param detail what it was inside of, or where, for a reader
 */
public record Violation(Kind kind, int tick, String ball, double amount, String detail) {

    /** The rules the checker enforces (issue 20, "Your own fuzz"). */
    public enum Kind {
        /** NaN or infinite (physics' vectors refuse NaN, so infinities are what can get in). */
        NOT_A_NUMBER("NaN"),
        ESCAPED("escapes"),
        INSIDE_GIZMO("inside a gizmo"),
        INSIDE_BALL("inside a ball"),
        ENERGY_GAINED("energy gained"),
        FROZEN("frozen"),
        /** A ball that appeared other than at a spawner's mouth with its velocity, or whose spawn no report named. */
        APPEARED("appeared"),
        /** A ball that left the board other than into a sink it touched, as the tick's report says. */
        VANISHED("vanished"),
        /** A ball that went through a portal not paired with the exit, or came out other than where the pair sends it. */
        JUMPED("jumped astray"),
        /**
         * A ball that does not move over a tick though its velocity (after friction and gravity) would move it, touching
         * nothing by more than the tolerance at either end of the tick, but near enough to something to have met it:
         * held apart from what it does not touch. Noted, not one of the rules: it does not make a run unclean.
         */
        HOVERING("hovering", false);

        private final String label;
        private final boolean rule;

        Kind(String label) {
            this(label, true);
        }

        Kind(String label, boolean rule) {
            this.label = label;
            this.rule = rule;
        }

        /** True for the rules of issue 20, which a clean run keeps; false for what is only noted. */
        public boolean rule() {
            return rule;
        }

        /** How a report's column names it. */
        public String label() {
            return label;
        }
    }

    @Override
    public String toString() {
        return "tick " + tick + ", ball " + ball + ": " + kind.label() + " (" + amount + ") " + detail;
    }
}
