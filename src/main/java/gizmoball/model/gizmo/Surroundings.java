package gizmoball.model.gizmo;

/**
 * What a driven gizmo's action does beyond the gizmo itself, to the board around it. The gizmo kinds may not see
 * the board (this package does not use {@code gizmoball.model}), so the board's play rules implement this and hand
 * it to {@link GizmoBase#act}, {@link GizmoBase#keyDown} and {@link GizmoBase#keyUp}.
 */
public interface Surroundings {

    /** The holder (an absorber) was triggered: it fires its longest-held ball, if the spot above it is free. */
    void fire(BallHolder holder);

    /**
     * The gate or drop target was told to be solid ({@code solid}: a gate closed, a target up) or nothing: it becomes
     * solid only over a clear cell, else waits as nothing until the cell is clear.
     */
    void switchCell(SwitchedCell cell, boolean solid);

    /** The source (a spawner) was told to spawn: a ball at its mouth, if it is free and the board has room for one more. */
    void spawn(BallSource source);

    /**
     * The gizmo started to swing ({@code up}: towards its raised stop), as a flipper does when driven: it is heard.
     * Told before it {@link #startedMoving}.
     */
    void swingStarted(String gizmo, boolean up);

    /**
     * The moving shape was driven from still to moving (a flipper starts to swing, a spinner to turn): it wakes the
     * balls in its box, where all of its sweep lies.
     */
    void startedMoving(MovingShape shape);
}
