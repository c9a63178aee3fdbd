package gizmoball.model.gizmo;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.Optional;
import java.util.function.Function;
import java.util.OptionalInt;

import physics.Vect;

/**
 * A rectangle of whole cells that captures every ball touching it, holds captured balls at its bottom-right
 * corner and, when triggered, fires the longest-held one straight up. A board can make it a {@link Plunger}: the key
 * that fires it then pulls it while held, and its release fires.
 */
public final class Absorber extends PolygonGizmo implements AbsorberView, BallHolder {
    private final int width;
    private final int height;
    /** Names of the balls held, in capture order (names keep deep copies of the board simple). */
    private final Deque<String> held = new ArrayDeque<>();
    private Optional<Plunger> plunger = Optional.empty();
    /** The key pulling it, while one is (play state, like a flipper's angle). */
    private OptionalInt pullingKey = OptionalInt.empty();
    /** Seconds of board time the pulling key has been held. */
    private double heldSeconds;

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
        this.plunger = other.plunger;
        this.pullingKey = other.pullingKey;
        this.heldSeconds = other.heldSeconds;
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
    @Override
    public Vect holdingPosition(double ballRadius) {
        return new Vect(x() + width - ballRadius, y() + height - ballRadius);
    }

    /**
     * Where a fired ball of radius {@code ballRadius} starts: right above the top edge, touching it, in the holding
     * column. For the board and its loop, not for views.
     */
    @Override
    public Vect launchPosition(double ballRadius) {
        return new Vect(x() + width - ballRadius, y() - ballRadius);
    }

    /** It holds the ball behind those it already holds, at its bottom-right corner. For the board. */
    @Override
    public Vect take(String ball, double ballRadius) {
        Vect at = holdingPosition(ballRadius);
        hold(ball);
        return at;
    }

    /** The names of the balls it holds, longest-held first (a copy: {@link #hold} and {@link #letGo} change them). */
    @Override
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

    @Override
    public void letGo(String ball) {
        held.remove(ball);
    }

    @Override
    public Optional<Plunger> plunger() {
        return plunger;
    }

    @Override
    public Setting setting() {
        return new Setting.Pull(plunger);
    }

    /** Makes it a plunger, or with an empty pull an absorber that fires at once. */
    @Override
    public void hold(Setting setting, Function<String, GizmoBase> gizmos) {
        plunger = ((Setting.Pull) setting).plunger();
        letGoOfPull();
    }

    @Override
    public double pull() {
        return plunger.isPresent() && pullingKey.isPresent() ? plunger.get().pullAfter(heldSeconds) : 0;
    }

    /** The key pulling it, if one is. For the board, not for views. */
    @Override
    public OptionalInt pullingKey() {
        return pullingKey;
    }

    /** The key starts to pull it, from no pull. For the board, not for views. */
    @Override
    public void startPull(int keyCode) {
        pullingKey = OptionalInt.of(keyCode);
        heldSeconds = 0;
    }

    /** The pulling key was held through a tick of {@code dt} seconds. For the board, not for views. */
    @Override
    public void heldFor(double dt) {
        heldSeconds += dt;
    }

    /**
     * The speed its release fires at now, after the time the key was held (a plunger that is pulled). For the board,
     * not for views.
     */
    @Override
    public double releaseSpeed() {
        return plunger.orElseThrow().speedAfter(heldSeconds);
    }

    /** The pull is over, released or dropped. For the board, not for views. */
    @Override
    public void letGoOfPull() {
        pullingKey = OptionalInt.empty();
        heldSeconds = 0;
    }

    /** The player's own when it is a plunger: a tilt leaves it dead. */
    @Override
    public boolean workedByPlayer() {
        return plunger.isPresent();
    }

    /** A tilt drops its pull, if it is being pulled, without firing. */
    @Override
    public void tilt(Surroundings around) {
        letGoOfPull();
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
