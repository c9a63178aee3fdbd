package gizmoball.lab;

import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.Sweep;
import java.util.Optional;

/**
 * The area a flipper sweeps on its way up, as a player judges it: the quarter disc about the pivot between the bar
 * at rest and the bar up, as far as the bar's length and the round end and a ball's radius reach. A ball centre in
 * it is one the swing can strike. (A ball just over the raised bar's line would be met too, at the end of the swing,
 * but counting those as in reach made the autoplayer flip too soon: on arcade.txt its mean score fell from 2,100 to
 * 1,300 with 0.2 L more.) Worked out once per flipper, so judging a point costs a few multiplications.
 */
final class FlipperReach {
    private final double pivotX;
    private final double pivotY;
    /** Unit vector from the pivot along the bar at rest. */
    private final double restX;
    private final double restY;
    /** Unit vector from the pivot along the bar raised. */
    private final double upX;
    private final double upY;
    private final double reachSquared;

    /** The reach of the gizmo if a key swings its bar (a flipper); empty for any other. */
    static Optional<FlipperReach> of(Gizmo gizmo) {
        return gizmo.sweep().map(FlipperReach::new);
    }

    private FlipperReach(Sweep sweep) {
        pivotX = sweep.pivot().x();
        pivotY = sweep.pivot().y();
        restX = sweep.rest().x();
        restY = sweep.rest().y();
        upX = sweep.up().x();
        upY = sweep.up().y();
        double reach = sweep.reach() + Board.BALL_RADIUS;
        reachSquared = reach * reach;
    }

    /** Whether a ball centred at (x, y) lies where the swing up strikes it. */
    boolean reaches(double x, double y) {
        double dx = x - pivotX;
        double dy = y - pivotY;
        double alongRest = dx * restX + dy * restY;
        double alongUp = dx * upX + dy * upY;
        return dx * dx + dy * dy <= reachSquared && alongRest >= 0 && alongUp >= 0;
    }
}
