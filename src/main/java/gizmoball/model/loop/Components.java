package gizmoball.model.loop;

/**
 * Vector arithmetic on components, for the loop's hot paths that would otherwise make a {@link physics.Vect} for
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
        return Math.hypot(x, y);
    }
}
