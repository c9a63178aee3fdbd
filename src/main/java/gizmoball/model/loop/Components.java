package gizmoball.model.loop;

import physics.Vect;

/**
 * Vector arithmetic on components, for the loop's hot paths that would otherwise make a {@link Vect} for
 * each step of a sum: each method gives the very doubles the {@code Vect} expression it names would hold.
 */
final class Components {
    private Components() {
    }

    /** {@code new Vect(x, y).length()}: exact along an axis, {@code hypot} otherwise. */
    static double length(double x, double y) {
        if (x == 0) {
            return Math.abs(y);
        }
        if (y == 0) {
            return Math.abs(x);
        }
        return StrictMath.hypot(x, y);
    }

    /**
     * One component of {@code new Vect(x, y).unitSize()}, without making it: {@code part} (x or y) over the
     * {@link #length} of (x, y), 0 where that is 0.
     */
    static double unitPart(double part, double length) {
        return length == 0 ? 0 : part / length + 0.0;
    }

    /** {@code new Vect(x, y).unitSize()}: the unit vector along (x, y), and {@code Vect.ZERO} for (0, 0). */
    static Vect unit(double x, double y) {
        double length = length(x, y);
        return length == 0 ? Vect.ZERO : new Vect(x / length, y / length);
    }
}
