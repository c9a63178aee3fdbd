package gizmoball.controller;

/**
 * How fast simulated time runs against the clock. Every speed ticks the same dt; a slower one only ticks
 * less often, so the physics (and so the path of every ball) is the same at every speed.
 */
public enum Speed {
    EIGHTH("1/8x", 0.125), QUARTER("1/4x", 0.25), HALF("1/2x", 0.5), NORMAL("1x", 1), DOUBLE("2x", 2);

    private final String label;
    private final double factor;

    Speed(String label, double factor) {
        this.label = label;
        this.factor = factor;
    }

    /** As the player reads it: "1/4x". */
    public String label() {
        return label;
    }

    /** Simulated seconds per real second. */
    public double factor() {
        return factor;
    }
}
