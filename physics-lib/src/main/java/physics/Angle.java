package physics;

import java.io.Serializable;

/**
 * An immutable direction, held as its cosine and sine (the package's representation, which its {@code toString}
 * shows). Positive angles turn +x toward +y (clockwise on a y-down screen); {@link #radians()} is in (-&pi;, &pi;].
 * <p>
 * Angles are directions: two angles are {@code equals} when their cosines and their sines each differ by at most
 * the comparison epsilon ({@value #DEFAULT_EPSILON} unless {@link #setEpsilon} says otherwise), so angles a whole
 * turn apart are equal. {@code compareTo} agrees with {@code equals} and otherwise orders by {@link #radians()}.
 * <p>
 * Quarter turns are exact: the constants at multiples of 45 degrees hold correctly rounded cosines and sines (0
 * and &plusmn;1 exactly at multiples of 90), and an angle given in radians within rounding of a multiple of
 * &pi;/2 ({@code Math.toRadians(-90)}, {@code 3 * Math.PI / 2}) is that quarter turn exactly, so that turning
 * points with integer coordinates by it gives integers, as games comparing turned shapes with {@code equals}
 * expect.
 */
public final class Angle implements Serializable, Comparable<Angle> {
    private static final long serialVersionUID = 2L;
    /** The default tolerance of {@code equals} and {@code compareTo} in cosine and sine (the package's). */
    static final double DEFAULT_EPSILON = 1e-6;
    private static final double HALF_SQRT_2 = StrictMath.sqrt(0.5);

    public static final Angle ZERO = new Angle(new Direction(1.0, 0.0));
    public static final Angle DEG_45 = new Angle(new Direction(HALF_SQRT_2, HALF_SQRT_2));
    public static final Angle DEG_90 = new Angle(new Direction(0.0, 1.0));
    public static final Angle DEG_135 = new Angle(new Direction(-HALF_SQRT_2, HALF_SQRT_2));
    public static final Angle DEG_180 = new Angle(new Direction(-1.0, 0.0));
    public static final Angle DEG_225 = new Angle(new Direction(-HALF_SQRT_2, -HALF_SQRT_2));
    public static final Angle DEG_270 = new Angle(new Direction(0.0, -1.0));
    public static final Angle DEG_315 = new Angle(new Direction(HALF_SQRT_2, -HALF_SQRT_2));
    public static final Angle RAD_PI_OVER_FOUR = DEG_45;
    public static final Angle RAD_PI_OVER_TWO = DEG_90;
    public static final Angle RAD_PI = DEG_180;

    /** Tolerance of {@code equals} and {@code compareTo}; volatile so that every thread sees a change at once. */
    private static volatile double epsilon = DEFAULT_EPSILON;

    private final double cos;
    private final double sin;

    /** A cosine and a sine exactly, for the named angles. */
    private record Direction(double cos, double sin) {
    }

    /**
     * The angle of so many radians, any value (NaN gives an angle whose cosine and sine are NaN, as in the package).
     * Within rounding of a multiple of pi/2 one of the cosine and sine is a rounding error of an exact 0, at most an
     * ulp of the argument: the caller meant that quarter turn, whose cosine and sine are 0 and +-1 exactly. Worked out
     * in the constructor, making nothing else: a swinging flipper makes an angle at every tick.
     */
    public Angle(double radians) {
        double c = StrictMath.cos(radians);
        double s = StrictMath.sin(radians);
        double rounding = Math.ulp(radians);
        if (Math.abs(c) <= rounding) {
            c = 0.0;
            s = Math.signum(s);
        } else if (Math.abs(s) <= rounding) {
            s = 0.0;
            c = Math.signum(c);
        }
        this.cos = c;
        this.sin = s;
    }

    /**
     * The direction of the vector (x, y) from +x.
     *
     * @throws IllegalArgumentException for (0, 0), which has no direction (as in the package)
     */
    public Angle(double x, double y) {
        if (x == 0 && y == 0) {
            throw new IllegalArgumentException("the vector (0, 0) has no direction");
        }
        double length = StrictMath.hypot(x, y);
        this.cos = x / length;
        this.sin = y / length;
    }

    private Angle(Direction direction) {
        this.cos = direction.cos;
        this.sin = direction.sin;
    }

    public double cos() {
        return cos;
    }

    public double sin() {
        return sin;
    }

    public double tan() {
        return sin / cos;
    }

    /** @return the angle in radians, in (-&pi;, &pi;] */
    public double radians() {
        return StrictMath.atan2(sin, cos);
    }

    /** The sum, by the addition theorems: exact for sums of quarter turns. */
    public Angle plus(Angle other) {
        return unit(cos * other.cos - sin * other.sin, sin * other.cos + cos * other.sin);
    }

    /** The difference, by the addition theorems: exact for differences of quarter turns. */
    public Angle minus(Angle other) {
        return unit(cos * other.cos + sin * other.sin, sin * other.cos - cos * other.sin);
    }

    /** The direction of (c, s), a vector of length 1 up to rounding, scaled back to length 1 (exactly so on an axis). */
    private static Angle unit(double c, double s) {
        double length = StrictMath.hypot(c, s);
        return new Angle(new Direction(c / length, s / length));
    }

    /**
     * Sets the tolerance in cosine and sine under which {@code equals} and {@code compareTo} call two angles equal
     * (default {@value #DEFAULT_EPSILON}).
     *
     * @throws IllegalArgumentException for a negative, infinite or NaN tolerance
     */
    public static void setEpsilon(double newEpsilon) {
        if (!(newEpsilon >= 0) || Double.isInfinite(newEpsilon)) {
            throw new IllegalArgumentException("epsilon must be finite and >= 0, got " + newEpsilon);
        }
        epsilon = newEpsilon;
    }

    /** 0 for equal angles ({@link #equals(Angle)}), else the order of {@link #radians()}. */
    @Override
    public int compareTo(Angle other) {
        if (equals(other)) {
            return 0;
        }
        return Double.compare(radians(), other.radians());
    }

    /** Whether the two directions agree within the epsilon in cosine and in sine. */
    public boolean equals(Angle other) {
        double tolerance = epsilon;
        return other != null && Math.abs(cos - other.cos) <= tolerance && Math.abs(sin - other.sin) <= tolerance;
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof Angle a && equals(a);
    }

    /**
     * One value for every angle: {@code equals} allows a tolerance, so angles whose cosines and sines differ by any
     * amount can be linked by a chain of equal ones, and only a constant keeps equal angles at equal hash codes.
     */
    @Override
    public int hashCode() {
        return Angle.class.hashCode();
    }

    /** {@code Angle(cos,sin)}, as the package prints it. */
    @Override
    public String toString() {
        return "Angle(" + cos + "," + sin + ")";
    }
}
