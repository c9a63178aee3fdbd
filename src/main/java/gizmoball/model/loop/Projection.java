package gizmoball.model.loop;

import java.util.List;

import physics.Vect;

/**
 * {@link Contacts#project} on the components, making nothing (stage 1 projects every awake ball's velocity in every
 * tick): which normal's part is removed ({@link #of}), then the projected velocity's components ({@link #x},
 * {@link #y}), the very doubles of the {@code Vect} arithmetic {@code v.minus(n.times(v.dot(n)))}.
 */
final class Projection {
    /** {@link #of}: the velocity closes on none of the surfaces and stays as it is. */
    static final int CLOSES_ON_NONE = -1;
    /** {@link #of}: no one normal's removal frees it; it becomes zero. */
    static final int WEDGED = -2;

    private Projection() {
    }

    /**
     * How (vx, vy) is projected on the surfaces with these normals: the index of the normal whose closing part is
     * removed (the least such part that leaves it closing on no other), {@link #CLOSES_ON_NONE} or {@link #WEDGED}.
     */
    static int of(double vx, double vy, List<Vect> normals) {
        int best = WEDGED;
        double bestChange = Double.POSITIVE_INFINITY;
        boolean closes = false;
        for (int i = 0; i < normals.size(); i++) {
            Vect n = normals.get(i);
            double along = vx * n.x() + vy * n.y();
            if (along >= 0) {
                continue;
            }
            closes = true;
            if (-along < bestChange && closesOnNone(withoutX(vx, vy, n), withoutY(vx, vy, n), normals)) {
                best = i;
                bestChange = -along;
            }
        }
        return closes ? best : CLOSES_ON_NONE;
    }

    /** The x of the projected (vx, vy), given its projection {@link #of}. */
    static double x(double vx, double vy, List<Vect> normals, int projection) {
        return projection == CLOSES_ON_NONE ? vx : projection == WEDGED ? 0 : withoutX(vx, vy, normals.get(projection));
    }

    /** The y of the projected (vx, vy), given its projection {@link #of}. */
    static double y(double vx, double vy, List<Vect> normals, int projection) {
        return projection == CLOSES_ON_NONE ? vy : projection == WEDGED ? 0 : withoutY(vx, vy, normals.get(projection));
    }

    /** The x of {@code v.minus(n.times(v.dot(n)))}, v = (vx, vy): v less its part along the unit normal. */
    private static double withoutX(double vx, double vy, Vect n) {
        return vx - (n.x() * (vx * n.x() + vy * n.y()) + 0.0) + 0.0;
    }

    /** The y of {@code v.minus(n.times(v.dot(n)))}. */
    private static double withoutY(double vx, double vy, Vect n) {
        return vy - (n.y() * (vx * n.x() + vy * n.y()) + 0.0) + 0.0;
    }

    /** Whether (vx, vy) closes on none of the surfaces by more than its own rounding. */
    private static boolean closesOnNone(double vx, double vy, List<Vect> normals) {
        double rounding = 1e-12 * Components.length(vx, vy);
        for (int i = 0; i < normals.size(); i++) {
            Vect n = normals.get(i);
            if (vx * n.x() + vy * n.y() < -rounding) {
                return false;
            }
        }
        return true;
    }
}
