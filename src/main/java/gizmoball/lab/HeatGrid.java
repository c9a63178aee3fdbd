package gizmoball.lab;

import gizmoball.model.Board;

/**
 * Where the balls went: the board cut into a fine grid, each cell counting the ticks that a free ball's centre spent
 * in it (time-weighted, since every tick is as long as the next). Whole counts add up the same in any order, so the
 * sum over games run on any number of threads is the same.
 */
public final class HeatGrid {
    /** Cells per L along each side. */
    public static final int CELLS_PER_L = 8;
    /** Cells along each side of the board. */
    public static final int SIDE = Board.SIZE * CELLS_PER_L;

    private final long[] ticks = new long[SIDE * SIDE];

    /** Counts one tick of a ball centred at (x, y) L; a centre on the board's edge counts in the edge cell. */
    void add(double x, double y) {
        ticks[cell(y) * SIDE + cell(x)]++;
    }

    private static int cell(double coordinate) {
        int cell = (int) (coordinate * CELLS_PER_L);
        return cell < 0 ? 0 : Math.min(cell, SIDE - 1);
    }

    /** Adds another grid's counts to this one's. */
    synchronized void addAll(HeatGrid other) {
        for (int i = 0; i < ticks.length; i++) {
            ticks[i] += other.ticks[i];
        }
    }

    /** The ticks counted in the cell at column {@code column} and row {@code row} (0 to {@link #SIDE} - 1). */
    public synchronized long ticksAt(int column, int row) {
        return ticks[row * SIDE + column];
    }

    /** The most ticks of any one cell. */
    public synchronized long maxTicks() {
        long max = 0;
        for (long count : ticks) {
            max = Math.max(max, count);
        }
        return max;
    }
}
