package gizmoball.lab;

import gizmoball.model.Board;

/**
 * Where the balls went: the board cut into a fine grid, each cell counting the time that a free ball's centre spent
 * in it, in {@link #WEIGHT}ths of a tick. A tick's weight is shared among points along the ball's flight in that tick
 * (a straight line: close enough within a tick), so a fast ball leaves a line rather than a trail of dots. Whole
 * counts add up the same in any order, so the sum over games run on any number of threads is the same.
 */
public final class HeatGrid {
    /** Cells per L along each side. */
    public static final int CELLS_PER_L = 8;
    /** Cells along each side of the board. */
    public static final int SIDE = Board.SIZE * CELLS_PER_L;

    private final long[] time = new long[SIDE * SIDE];

    /** The count of one tick in one cell. */
    public static final int WEIGHT = 60;
    /** Points along a tick's flight per cell it crosses. */
    private static final int POINTS_PER_CELL = 2;

    /**
     * Counts one tick of a ball that flew from (fromX, fromY) to (x, y) L, its weight shared evenly among points
     * along the line (a flight of NaN, or longer than {@code longestStep}: a ball that appeared or jumped, counted
     * where it is). A centre on the board's edge counts in the edge cell.
     */
    void addPath(double fromX, double fromY, double x, double y, double longestStep) {
        double dx = x - fromX;
        double dy = y - fromY;
        double length = Math.sqrt(dx * dx + dy * dy);
        if (!(length <= longestStep)) {
            time[cell(y) * SIDE + cell(x)] += WEIGHT;
            return;
        }
        int points = Math.max(1, Math.min(WEIGHT, (int) Math.ceil(length * CELLS_PER_L * POINTS_PER_CELL)));
        int share = WEIGHT / points;
        for (int i = 1; i <= points; i++) {
            double f = (double) i / points;
            time[cell(fromY + dy * f) * SIDE + cell(fromX + dx * f)] += share;
        }
    }

    private static int cell(double coordinate) {
        int cell = (int) (coordinate * CELLS_PER_L);
        return cell < 0 ? 0 : Math.min(cell, SIDE - 1);
    }

    /** Adds another grid's counts to this one's. */
    synchronized void addAll(HeatGrid other) {
        for (int i = 0; i < time.length; i++) {
            time[i] += other.time[i];
        }
    }

    /** The time counted in the cell at column {@code column} and row {@code row} (0 to {@link #SIDE} - 1). */
    public synchronized long timeAt(int column, int row) {
        return time[row * SIDE + column];
    }

    /** The most time of any one cell. */
    public synchronized long maxTime() {
        long max = 0;
        for (long count : time) {
            max = Math.max(max, count);
        }
        return max;
    }
}
