package gizmoball.model.gizmo;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;

import physics.Vect;

/**
 * A rectangle of whole cells that captures every ball touching it, holds captured balls at its bottom-right
 * corner and, when triggered, fires the longest-held one straight up.
 */
public final class Absorber extends PolygonGizmo implements AbsorberView {
    private final int width;
    private final int height;
    /** Names of the balls held, in capture order (names keep deep copies of the board simple). */
    private final Deque<String> held = new ArrayDeque<>();

    /**
     * An absorber of width x height cells with its top-left cell at (x, y), holding nothing. For the board and its
     * loop, not for views.
     */
    public Absorber(String name, int x, int y, int width, int height) {
        super(name, GizmoKind.ABSORBER, x, y);
        this.width = width;
        this.height = height;
        rebuildShape();
    }

    private Absorber(Absorber other, int width, int height) {
        super(other);
        this.width = width;
        this.height = height;
        this.held.addAll(other.held);
    }

    /**
     * A copy of it (name, colour, the balls it holds) covering width x height cells from (x, y): what a resize
     * would make, for the board to check and then put in its place. For the board, not for views.
     */
    public Absorber resized(int newX, int newY, int newWidth, int newHeight) {
        Absorber resized = new Absorber(this, newWidth, newHeight);
        resized.moveTo(newX, newY);
        return resized;
    }

    @Override
    public int width() {
        return width;
    }

    @Override
    public int height() {
        return height;
    }

    @Override
    public double reflectionCoefficient() {
        return 0;
    }

    @Override
    List<Vect> outline() {
        int x = x();
        int y = y();
        return List.of(new Vect(x, y), new Vect(x + width, y), new Vect(x + width, y + height), new Vect(x, y + height));
    }

    /**
     * Where the centre of a captured ball of radius {@code ballRadius} sits: the bottom-right corner, ball inside.
     * For the board and its loop, not for views.
     */
    public Vect holdingPosition(double ballRadius) {
        return new Vect(x() + width - ballRadius, y() + height - ballRadius);
    }

    /**
     * Where a fired ball of radius {@code ballRadius} starts: right above the top edge, touching it, in the holding
     * column. For the board and its loop, not for views.
     */
    public Vect launchPosition(double ballRadius) {
        return new Vect(x() + width - ballRadius, y() - ballRadius);
    }

    /** The names of the balls it holds, longest-held first (a copy: {@link #hold} and {@link #letGo} change them). */
    public List<String> held() {
        return List.copyOf(held);
    }

    /**
     * It holds the ball named {@code ball} too, behind those it already holds. For the board and its loop, not for
     * views.
     */
    public void hold(String ball) {
        held.addLast(ball);
    }

    /**
     * It no longer holds the ball named {@code ball} (fired, moved or deleted), if it did. For the board and its loop,
     * not for views.
     */
    public void letGo(String ball) {
        held.remove(ball);
    }

    /** Fires the longest-held ball, if the spot above is free. */
    @Override
    public void act(Surroundings around) {
        around.fire(this);
    }

    @Override
    public Absorber copy() {
        return new Absorber(this, width, height);
    }
}
