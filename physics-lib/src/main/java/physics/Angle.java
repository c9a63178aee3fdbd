package physics;

import java.io.Serializable;

/**
 * An immutable angle, stored only as radians normalised to [0, 2&pi;).
 * Positive angles turn +x toward +y (clockwise on a y-down screen).
 * <p>
 * {@code equals} and {@code hashCode} compare the normalised radians exactly. {@code compareTo} orders by
 * the normalised radians and treats angles closer than the comparison epsilon as equal; the epsilon is 0 by
 * default, so by default {@code compareTo} is consistent with {@code equals}.
 */
public final class Angle implements Serializable, Comparable<Angle> {
    private static final long serialVersionUID = 1L;
    private static final double TWO_PI = 2 * Math.PI;

    public static final Angle ZERO = new Angle(0);
    public static final Angle DEG_45 = new Angle(Math.PI / 4);
    public static final Angle DEG_90 = new Angle(Math.PI / 2);
    public static final Angle DEG_135 = new Angle(3 * Math.PI / 4);
    public static final Angle DEG_180 = new Angle(Math.PI);
    public static final Angle DEG_225 = new Angle(5 * Math.PI / 4);
    public static final Angle DEG_270 = new Angle(3 * Math.PI / 2);
    public static final Angle DEG_315 = new Angle(7 * Math.PI / 4);
    public static final Angle RAD_PI_OVER_FOUR = DEG_45;
    public static final Angle RAD_PI_OVER_TWO = DEG_90;
    public static final Angle RAD_PI = DEG_180;

    /** Tolerance of {@link #compareTo(Angle)} only; volatile so that every thread sees a change at once. */
    private static volatile double comparisonEpsilon = 0;

    private final double radians;

    /** @param radians any finite angle in radians; it is normalised to [0, 2&pi;) */
    public Angle(double radians) {
        if (!Double.isFinite(radians)) {
            throw new IllegalArgumentException("angle must be finite, got " + radians);
        }
        double r = radians % TWO_PI;
        if (r < 0) {
            r += TWO_PI;
        }
        // r + 2pi can round up to exactly 2pi for a tiny negative r; + 0.0 turns -0.0 into 0.0.
        this.radians = (r >= TWO_PI ? 0 : r) + 0.0;
    }

    /** The angle of the vector (x, y) from +x; the zero vector has angle 0 (a defined answer, not NaN). */
    public Angle(double x, double y) {
        this(Math.atan2(y, x));
    }

    public double cos() {
        return Math.cos(radians);
    }

    public double sin() {
        return Math.sin(radians);
    }

    public double tan() {
        return Math.tan(radians);
    }

    /** @return the angle in radians, in [0, 2&pi;) */
    public double radians() {
        return radians;
    }

    public Angle plus(Angle other) {
        return new Angle(radians + other.radians);
    }

    public Angle minus(Angle other) {
        return new Angle(radians - other.radians);
    }

    /**
     * Sets the tolerance under which {@link #compareTo(Angle)} calls two angles equal (default 0: exact).
     * It never affects {@code equals} or {@code hashCode}, which stay exact and consistent with each other.
     */
    public static void setEpsilon(double epsilon) {
        if (!(epsilon >= 0) || Double.isInfinite(epsilon)) {
            throw new IllegalArgumentException("epsilon must be finite and >= 0, got " + epsilon);
        }
        comparisonEpsilon = epsilon;
    }

    @Override
    public int compareTo(Angle other) {
        if (Math.abs(radians - other.radians) <= comparisonEpsilon) {
            return 0;
        }
        return Double.compare(radians, other.radians);
    }

    public boolean equals(Angle other) {
        return other != null && radians == other.radians;
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof Angle a && equals(a);
    }

    @Override
    public int hashCode() {
        return Double.hashCode(radians);
    }

    @Override
    public String toString() {
        return "Angle(" + radians + " rad)";
    }
}
