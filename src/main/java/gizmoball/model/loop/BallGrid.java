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

    /** Empty; the loop files the balls at each tick. The board keeps one for its loop, not for views. */
    public BallGrid() {
        for (int i = 0; i < Arena.SIZE * Arena.SIZE; i++) {
            cells.add(new ArrayList<>(2));
        }
    }

    void clear() {
        cells.forEach(List::clear);
    }

    void add(Ball ball) {
        cells.get(index(cell(ball.position().x()), cell(ball.position().y()))).add(ball);
    }

    /** Every filed ball whose filed centre lies within the square of half-side {@code reach} around (x, y). */
    void near(double x, double y, double reach, List<Ball> into) {
        int x0 = cell(x - reach);
        int x1 = cell(x + reach);
        int y0 = cell(y - reach);
        int y1 = cell(y + reach);
        for (int cy = y0; cy <= y1; cy++) {
            for (int cx = x0; cx <= x1; cx++) {
                List<Ball> cell = cells.get(index(cx, cy));
                for (int i = 0, n = cell.size(); i < n; i++) {   // addAll would copy each cell into an array
                    into.add(cell.get(i));
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
