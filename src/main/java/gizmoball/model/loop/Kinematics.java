package gizmoball.model.loop;

import physics.Vect;

/**
 * The motion of two things that touch, as the detector, a contact and a cluster all reckon it: the velocity of a
 * turning body's surface, and whether a round contact only grazes. One home, so that what one of them lets pass the
 * others do not meet again at once.
 */
final class Kinematics {
    private Kinematics() {
    }

    /** Velocity of the point of a body turning at omega about the pivot (the library's sense: +x toward +y). */
    static Vect surfaceVelocity(Vect pivot, double omega, Vect point) {
        return new Vect(-omega * (point.y() - pivot.y()), omega * (point.x() - pivot.x()));
    }

    /**
     * Whether a round contact (another ball, a circle), {@code offset} from its centre and touching at {@code touch}
     * apart, closes only as a graze: along the straight relative motion the two come no nearer than {@code touch}
     * less {@link Tolerances#PLACEMENT}, so left alone they overlap by no more than what counts as touching. Two
     * balls sliding past each other in a gap that just fits them close so until they pass (a tilt of 4e-5 rad is a
     * closing speed of 4e-5 of their speed), and resolving that as a contact asks for impulses some 30,000 times their
     * speed, past any velocity the walls beside them allow. The detector and the cluster ask the same, so neither
     * meets again at once what the other let pass.
     */
    static boolean grazes(Vect offset, Vect relative, double touch) {
        return grazes(offset.x(), offset.y(), relative.x(), relative.y(), touch);
    }

    /** {@link #grazes(Vect, Vect, double)} on the components, so that the cluster asks it of each pair making none. */
    static boolean grazes(double offsetX, double offsetY, double relativeX, double relativeY, double touch) {
        double closing = -(relativeX * offsetX + relativeY * offsetY);
        double speed = Components.length(relativeX, relativeY);
        if (closing <= 0 || speed == 0) {
            return false;
        }
        double nearest = Math.abs(offsetX * relativeY - offsetY * relativeX) / speed;
        return nearest >= touch - Tolerances.PLACEMENT;
    }
}
