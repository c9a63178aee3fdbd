package gizmoball.model;

import physics.Circle;
import physics.LineSegment;

/** What a ball is about to hit; stage 4 resolves each kind with the matching physics-lib reflect method. */
sealed interface Contact {

    /** A fixed segment of a bumper or absorber, or of the outer walls when {@code gizmo} is null. */
    record Wall(LineSegment segment, GizmoBase gizmo) implements Contact {
    }

    /** A fixed circle of a bumper or absorber: a circle bumper or a zero-radius corner. */
    record Round(Circle circle, GizmoBase gizmo) implements Contact {
    }

    /**
     * A part of a flipper's shape, taken at the time of contact: side segment {@code index} or, when
     * {@code circle}, end circle {@code index} ({@link Flipper#PIVOT_CIRCLE}, {@link Flipper#TIP_CIRCLE}).
     */
    record FlipperPart(Flipper flipper, boolean circle, int index) implements Contact {
    }

    record OtherBall(Ball other) implements Contact {
    }
}
