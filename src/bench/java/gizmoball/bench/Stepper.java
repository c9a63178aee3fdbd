package gizmoball.bench;

import gizmoball.model.gizmo.Gizmo;

import java.util.List;

/** A board being stepped by one of the loops. */
interface Stepper {

    void tick(double dt);

    void keyDown(int keyCode);

    void keyUp(int keyCode);

    /** Balls in the scene's order. */
    List<BallState> balls();

    /** Gizmos at their current state (flipper angles). */
    List<Gizmo> gizmos();

    /** Sum over free balls of |v|^2/2 + g (SIZE - y), unit mass, as Board.energy() defines it. */
    double energy();

    /** Whether the model's own Invariants check applies to this loop. */
    boolean checksModelInvariants();

    /** Whether the model's Invariants hold now (only where {@link #checksModelInvariants()}). */
    boolean modelInvariantsHold();
}
