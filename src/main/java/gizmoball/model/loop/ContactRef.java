package gizmoball.model.loop;

import java.util.List;

/**
 * What a ball lies on, rolls along or is wedged against: a persistent contact (docs/design.md, "Resting and
 * rolling contact"). It names the surface rather than holding its geometry, so a copy of the board keeps its
 * contacts and an edit that rebuilds a shape can never leave a ball attached to a stale one.
 */
sealed interface ContactRef {

    /** Outer wall {@code side}: 0 top, 1 right, 2 bottom, 3 left. */
    record Wall(int side) implements ContactRef {
        private static final List<Wall> SIDES = List.of(new Wall(0), new Wall(1), new Wall(2), new Wall(3));

        /** The wall of that side, made once (a reference is a value). */
        static Wall of(int side) {
            return SIDES.get(side);
        }
    }

    /** Segment or circle {@code index} of the named gizmo's shape at rest (a flipper counts only while still). */
    record Part(String gizmo, boolean circle, int index) implements ContactRef {
    }

    /** Another ball, lying still or itself supported: the contact treats it as fixed. */
    record OnBall(String ball) implements ContactRef {
    }
}
