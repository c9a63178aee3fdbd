package gizmoball.model.loop;

/**
 * The rows of one contact cluster's normal impulses ({@link NormalImpulses}): per row, the ball the normal points into,
 * the other ball or a surface, the unit normal, and the surface's speed along it; and what an impulse on a row does.
 */
final class ContactRows {
    /**
     * L/s: a row closing no faster than this is left alone, as the detector leaves a touch closing slower than
     * {@link Tolerances#ROUNDING_SPEED}: the rounding of a normal that is nearly square to a motion (two balls side by
     * side in a gap that fits them, one sliding past the other) asks for impulses without end to undo it.
     */
    static final double SLOP = Tolerances.ROUNDING_SPEED / 2;

    private final int balls;
    private final int[] a;
    private final int[] b;
    private final double[] nx;
    private final double[] ny;
    private final double[] speed;

    /** As {@link NormalImpulses#NormalImpulses}'s arguments of the same names. */
    ContactRows(int balls, int[] a, int[] b, double[] nx, double[] ny, double[] speed) {
        this.balls = balls;
        this.a = a;
        this.b = b;
        this.nx = nx;
        this.ny = ny;
        this.speed = speed;
    }

    int balls() {
        return balls;
    }

    int count() {
        return a.length;
    }

    /** The surface's speed along row i's normal (0 for a ball or a still surface). */
    double speed(int i) {
        return speed[i];
    }

    /** How much one unit of impulse on the row changes what it closes by: 1 on a surface, 2 between two balls. */
    double diagonal(int i) {
        return b[i] < 0 ? 1 : 2;
    }

    /** What row i closes by at the velocities (vx, vy): the surface's speed less the balls' relative one. */
    double closing(double[] vx, double[] vy, int i) {
        double ux = vx[a[i]];
        double uy = vy[a[i]];
        if (b[i] >= 0) {
            ux -= vx[b[i]];
            uy -= vy[b[i]];
        }
        return speed[i] - (ux * nx[i] + uy * ny[i]);
    }

    /** J_i . J_j: how an impulse on row j changes what row i closes by. */
    double coupling(int i, int j) {
        double dot = nx[i] * nx[j] + ny[i] * ny[j];
        double sum = 0;
        if (a[i] == a[j]) {
            sum += dot;
        }
        if (b[i] >= 0 && b[i] == a[j]) {
            sum -= dot;
        }
        if (b[j] >= 0 && a[i] == b[j]) {
            sum -= dot;
        }
        if (b[i] >= 0 && b[i] == b[j]) {
            sum += dot;
        }
        return sum;
    }

    /** Stops the balls of row i in the velocities (x, y); returns whether one of them was moving. */
    boolean rest(double[] x, double[] y, int i) {
        boolean moved = x[a[i]] != 0 || y[a[i]] != 0;
        x[a[i]] = 0;
        y[a[i]] = 0;
        if (b[i] >= 0) {
            moved |= x[b[i]] != 0 || y[b[i]] != 0;
            x[b[i]] = 0;
            y[b[i]] = 0;
        }
        return moved;
    }

    /** Adds {@code amount} of impulse on row i to the velocities (x, y). */
    void addImpulse(double[] x, double[] y, int i, double amount) {
        x[a[i]] += amount * nx[i];
        y[a[i]] += amount * ny[i];
        if (b[i] >= 0) {
            x[b[i]] -= amount * nx[i];
            y[b[i]] -= amount * ny[i];
        }
    }
}
