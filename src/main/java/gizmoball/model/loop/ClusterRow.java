package gizmoball.model.loop;

import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.MovingShape;

import java.util.List;

import physics.Vect;

/**
 * One contact of a {@link ContactCluster}: ball {@code ball} (an index) touches {@code other}, with the unit normal
 * (normalX, normalY) toward the ball, as a {@code Vect} holds it, the surface's speed along it and the coefficient of
 * the bounce. The cluster keeps its rows from one gathering to the next and sets them afresh, as Box2D's step takes
 * its contacts from an arena: a row and its normal, made for each contact of each solve, were a fifth of what a tick of
 * the 100-ball peer board allocated (docs/design.md, "What a tick allocates"). A row is the cluster's until it gathers
 * again.
 */
final class ClusterRow {

    /** What a row of the cluster is a contact with. */
    sealed interface Other {
        /** What a ball of the cluster ({@code balls}, by index) struck when this row takes an impact. */
        Struck struck(List<Ball> balls);

        /** A surface, still or moving, rather than a ball: an impact on it is measured against the resting speed. */
        sealed interface Surface extends Other {
        }

        /** A still surface; {@code gizmo} null for an outer wall. */
        record Still(ContactRef ref, GizmoBase gizmo) implements Surface {
            @Override
            public Struck struck(List<Ball> balls) {
                return gizmo == null ? TriggerSource.OUTER_WALLS : TriggerSource.gizmo(gizmo.name());
            }
        }

        /** A part of a moving shape. */
        record Moving(MovingShape shape) implements Surface {
            @Override
            public Struck struck(List<Ball> balls) {
                return TriggerSource.gizmo(shape.name());
            }
        }

        /** A ball of the cluster, by its index. */
        record InCluster(int index) implements Other {
            @Override
            public Struck struck(List<Ball> balls) {
                return balls.get(index).asStruck();
            }
        }

        /**
         * A ball beyond the cluster's limit, taken as a surface moving as it moves now where it moves away, and as a
         * still one where it presses in ({@code ContactCluster.beyondSpeed}).
         */
        record Beyond(Ball ball) implements Other {
            @Override
            public Struck struck(List<Ball> balls) {
                return ball.asStruck();
            }
        }
    }

    private int ball;
    private Other other;
    private double normalX;
    private double normalY;
    /** The normal as a vector, made when first asked for (most rows are only ever read by component). */
    private Vect normal;
    private double surfaceSpeed;
    private double restitution;

    /** This row, set to the contact given; {@code normal} is (normalX, normalY) if already made, else null. */
    ClusterRow set(int ball, Other other, double normalX, double normalY, Vect normal,
                   double surfaceSpeed, double restitution) {
        this.ball = ball;
        this.other = other;
        this.normalX = normalX;
        this.normalY = normalY;
        this.normal = normal;
        this.surfaceSpeed = surfaceSpeed;
        this.restitution = restitution;
        return this;
    }

    int ball() {
        return ball;
    }

    Other other() {
        return other;
    }

    double normalX() {
        return normalX;
    }

    double normalY() {
        return normalY;
    }

    Vect normal() {
        if (normal == null) {
            normal = new Vect(normalX, normalY);
        }
        return normal;
    }

    double surfaceSpeed() {
        return surfaceSpeed;
    }

    double restitution() {
        return restitution;
    }
}
