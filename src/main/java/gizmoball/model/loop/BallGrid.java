package gizmoball.model.loop;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The broad phase for ball pairs: free balls filed by the cell their centre was in when filed, each cell with the
 * highest speed of its balls since. Positions go stale as balls move on within a tick, so a query widens its radius
 * by how far any ball can have moved since, and passes over a cell whose balls are too slow to come within reach:
 * balls far apart are never asked about each other, and a fast ball does not make every query read the cells of
 * slow ones (docs/design.md, "Detection asks only about what can be reached").
 */
public final class BallGrid {
    private static final int CELLS = Arena.SIZE * Arena.SIZE;
    private final List<List<Ball>> cells = new ArrayList<>(CELLS);
    /** By cell: the highest speed (L/s) of a ball filed there, since it was filed. */
    private final double[] cellFastest = new double[CELLS];
    /** The cells holding a ball, so that clearing costs the balls filed, not the 400 cells. */
    private final int[] filled = new int[CELLS];
    private int filledCount;
    /** By slot ({@link Ball#slot()}): the cell the ball was filed in. */
    private int[] cellOfSlot = new int[0];

    /** Empty; the loop files the balls at each tick. The board keeps one for its loop, not for views. */
    public BallGrid() {
        for (int i = 0; i < CELLS; i++) {
            cells.add(new ArrayList<>(2));
        }
    }

    /** Empty, ready for {@code balls} balls in slots 0 to balls - 1. */
    void clear(int balls) {
        for (int k = 0; k < filledCount; k++) {
            cells.get(filled[k]).clear();
            cellFastest[filled[k]] = 0;
        }
        filledCount = 0;
        if (cellOfSlot.length < balls) {
            cellOfSlot = new int[Math.max(balls, 2 * cellOfSlot.length)];
        }
    }

    /** Files the ball, in its slot, where it is now, moving at {@code speed} (L/s). */
    void add(Ball ball, double speed) {
        int index = index(cell(ball.x()), cell(ball.y()));
        List<Ball> cell = cells.get(index);
        if (cell.isEmpty()) {
            filled[filledCount++] = index;
        }
        cell.add(ball);
        cellOfSlot[ball.slot()] = index;
        sped(ball, speed);
    }

    /** The filed ball moves at {@code speed} (L/s) now: its cell's balls may go farther. */
    void sped(Ball ball, double speed) {
        int index = cellOfSlot[ball.slot()];
        cellFastest[index] = Math.max(cellFastest[index], speed);
    }

    /**
     * Every filed ball whose centre lies now within the square of half-side {@code near} around (x, y), looked for
     * among the balls filed within {@code reach} of it ({@code reach} covers how far any ball moved since it was
     * filed), in the order of their cells, row by row, and of their filing in a cell. The test on where a ball is now
     * keeps out the balls that filed cells bring in but that lie too far for any pair test to accept: in a pile of
     * 100 balls, three in four of those the cells give.
     *
     * <p>A cell is passed over when none of its balls can be within reach of a ball at (x, y) moving at s: they are
     * no faster than the cell's fastest f, so they are now within f {@code stale} of the cell, and a pair farther
     * apart than {@code alone} + f {@code window} (alone: 2 r + s window and a margin) cannot meet in the window.
     * That is the pair test's own bound (the two balls' relative speed is at most s + f), so no pair that could meet
     * is passed over, and the balls found come in the same order.
     */
    void near(double x, double y, double reach, double near, double alone, double window, double stale,
              List<Ball> into) {
        int x0 = cell(x - reach);
        int x1 = cell(x + reach);
        int y0 = cell(y - reach);
        int y1 = cell(y + reach);
        for (int cy = y0; cy <= y1; cy++) {
            double dy = Math.max(0, Math.max(cy - y, y - (cy + 1)));
            for (int cx = x0; cx <= x1; cx++) {
                int index = index(cx, cy);
                List<Ball> cell = cells.get(index);
                int n = cell.size();
                if (n == 0) {
                    continue;
                }
                double fastest = cellFastest[index];
                double within = alone + fastest * window + fastest * stale;
                if (dy > within || Math.max(0, Math.max(cx - x, x - (cx + 1))) > within) {
                    continue;
                }
                for (int i = 0; i < n; i++) {
                    Ball ball = cell.get(i);
                    if (Math.abs(ball.x() - x) <= near && Math.abs(ball.y() - y) <= near) {
                        into.add(ball);
                    }
                }
            }
        }
    }

    private static int index(int cx, int cy) {
        return cy * Arena.SIZE + cx;
    }

    private static int cell(double coordinate) {
        return (int) Math.max(0, Math.min(Arena.SIZE - 1, Math.floor(coordinate)));
    }
}
