package gizmoball.model.loop;

import java.util.Arrays;

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

    private int balls;
    private int count;
    private int[] a = new int[0];
    private int[] b = new int[0];
    private double[] nx = new double[0];
    private double[] ny = new double[0];
    private double[] speed = new double[0];

    /** Starts a new set of rows on {@code balls} balls; the arrays are kept and grow with the largest set seen. */
    void clear(int balls) {
        this.balls = balls;
        this.count = 0;
    }

    /** Adds a row, as {@link NormalImpulses#row}'s arguments of the same names. */
    void add(int a, int b, double nx, double ny, double speed) {
        if (count == this.a.length) {
            int capacity = Math.max(8, 2 * count);
            this.a = Arrays.copyOf(this.a, capacity);
            this.b = Arrays.copyOf(this.b, capacity);
            this.nx = Arrays.copyOf(this.nx, capacity);
            this.ny = Arrays.copyOf(this.ny, capacity);
            this.speed = Arrays.copyOf(this.speed, capacity);
        }
        this.a[count] = a;
        this.b[count] = b;
        this.nx[count] = nx;
        this.ny[count] = ny;
        this.speed[count] = speed;
        count++;
    }

    int balls() {
        return balls;
    }

    int count() {
        return count;
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
