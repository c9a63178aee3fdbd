package gizmoball.lab;

import gizmoball.model.Board;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import java.util.Optional;
import physics.Vect;

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

    /** The reach of the gizmo if it is a flipper; empty for any other. */
    static Optional<FlipperReach> of(Gizmo gizmo) {
        return gizmo instanceof FlipperView flipper ? Optional.of(new FlipperReach(flipper)) : Optional.empty();
    }

    private FlipperReach(FlipperView flipper) {
        Vect pivot = flipper.pivot();
        pivotX = pivot.x();
        pivotY = pivot.y();
        // At rest a flipper of rotation 0 hangs straight down; each quarter turn turns it clockwise on the screen
        // (y grows downward, so clockwise takes (x, y) to (-y, x)).
        double x = 0;
        double y = 1;
        for (int turn = 0; turn < flipper.rotation(); turn++) {
            double turned = -y;
            y = x;
            x = turned;
        }
        restX = x;
        restY = y;
        // Up is a quarter turn from rest: anticlockwise on the screen for a left flipper (down to the right), clockwise
        // for a right one (down to the left).
        if (flipper.kind() == GizmoKind.LEFT_FLIPPER) {
            upX = y;
            upY = -x;
        } else {
            upX = -y;
            upY = x;
        }
        double length = flipper.tip().minus(pivot).length();
        double reach = length + flipper.radius() + Board.BALL_RADIUS;
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
