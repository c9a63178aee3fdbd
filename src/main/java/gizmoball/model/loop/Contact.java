package gizmoball.model.loop;

import gizmoball.model.gizmo.Flipper;
import gizmoball.model.gizmo.GizmoBase;

import physics.Circle;
import physics.LineSegment;

/** What a ball is about to hit; stage 4 resolves each kind with the matching physics-lib reflect method. */
sealed interface Contact {

    /** What the ball hits: the outer walls, a gizmo (a trigger source) or another ball. */
    Struck struck();

    /** Outer wall {@code side} (0 top, 1 right, 2 bottom, 3 left). */
    record OuterWall(int side, LineSegment segment) implements Contact {
        @Override
        public Struck struck() {
            return TriggerSource.OUTER_WALLS;
        }
    }

    /** Segment {@code index} of a still gizmo's shape: a side of a polygon bumper, an absorber or a still flipper. */
    record Face(GizmoBase gizmo, int index, LineSegment segment) implements Contact {
        @Override
        public Struck struck() {
            return TriggerSource.gizmo(gizmo.name());
        }
    }

    /**
     * Circle {@code index} of a still gizmo's shape: a circle bumper, a zero-radius polygon corner or a still
     * flipper's round end.
     */
    record Round(GizmoBase gizmo, int index, Circle circle) implements Contact {
        @Override
        public Struck struck() {
            return TriggerSource.gizmo(gizmo.name());
        }
    }

    /**
     * A part of a swinging flipper's shape as it is now: side segment {@code index} or, when {@code circle}, end
     * circle {@code index} ({@link Flipper#PIVOT_CIRCLE}, {@link Flipper#TIP_CIRCLE}).
     */
    record SwingingPart(Flipper flipper, boolean circle, int index) implements Contact {
        @Override
        public Struck struck() {
            return TriggerSource.gizmo(flipper.name());
        }
    }

    record OtherBall(Ball other) implements Contact {
        @Override
        public Struck struck() {
            return new Struck.OtherBall(other.name());
        }
    }
}
