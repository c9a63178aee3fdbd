package gizmoball.model.loop;

import java.util.ArrayList;
import java.util.List;

/**
 * The broad phase for ball pairs: free balls filed by the cell their centre was in when filed. Positions go stale as
 * balls move on within a tick, so a query widens its radius by how far any ball can have moved since; balls far
 * apart are never asked about each other (docs/design.md, "Detection asks only about what can be reached").
 */
public final class BallGrid {
    private final List<List<Ball>> cells = new ArrayList<>(Arena.SIZE * Arena.SIZE);
    /** The cells holding a ball, so that clearing costs the balls filed, not the 400 cells. */
    private final List<List<Ball>> filled = new ArrayList<>();

    /** Empty; the loop files the balls at each tick. The board keeps one for its loop, not for views. */
    public BallGrid() {
        for (int i = 0; i < Arena.SIZE * Arena.SIZE; i++) {
            cells.add(new ArrayList<>(2));
        }
    }

    void clear() {
        filled.forEach(List::clear);
        filled.clear();
    }

    void add(Ball ball) {
        List<Ball> cell = cells.get(index(cell(ball.x()), cell(ball.y())));
        if (cell.isEmpty()) {
            filled.add(cell);
        }
        cell.add(ball);
    }

    /**
     * Every filed ball whose centre lies now within the square of half-side {@code near} around (x, y), looked for
     * among the balls filed within {@code reach} of it ({@code reach} covers how far any ball moved since it was
     * filed). The test on where a ball is now keeps out the balls that filed cells bring in but that lie too far for
     * any pair test to accept: in a pile of 100 balls, three in four of those the cells give.
     */
    void near(double x, double y, double reach, double near, List<Ball> into) {
        int x0 = cell(x - reach);
        int x1 = cell(x + reach);
        int y0 = cell(y - reach);
        int y1 = cell(y + reach);
        for (int cy = y0; cy <= y1; cy++) {
            for (int cx = x0; cx <= x1; cx++) {
                List<Ball> cell = cells.get(index(cx, cy));
                for (int i = 0, n = cell.size(); i < n; i++) {
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
