package gizmoball.model.loop;

import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.MovingShape;
import gizmoball.model.gizmo.Shape;

import java.util.function.Function;

import physics.Circle;
import physics.Geometry;
import physics.LineSegment;
import physics.Vect;

/**
 * What a ball is about to hit, or touches: a still surface, a part of a moving shape or another ball. Each kind says
 * what the loop asks of it (what it is, its normal, how its surface moves); stage 4 resolves a still surface with
 * the matching physics-lib reflect method ({@link StillSurface#reflect}), a moving part and a ball with their own.
 */
sealed interface Contact {

    /** What the ball hits: the outer walls, a gizmo (a trigger source) or another ball. */
    Struck struck();

    /** The unit normal from this contact toward a ball centred at {@code centre}, as the contact is now. */
    Vect normal(Vect centre);

    /**
     * This contact as a side of a {@link Squeeze}, for a ball centred at {@code centre}: its normal, and the speed of
     * its surface along it, other balls moving as {@code motion} says.
     */
    default Squeeze.Side side(Vect centre, Function<Ball, Vect> motion) {
        return new Squeeze.Side(normal(centre), 0);
    }

    /** A surface that does not move: an outer wall or a part of a still gizmo. */
    sealed interface StillSurface extends Contact {
        /** The gizmo it belongs to; null for an outer wall. */
        GizmoBase gizmo();

        /** The reference the ball keeps when it comes to rest on it. */
        ContactRef ref();

        /** {@link #normal} toward the ball where it is now. */
        default Vect normalTo(Ball ball) {
            return normal(ball.position());
        }

        /** The velocity of the ball, moving at {@code velocity}, after it bounces off with this coefficient. */
        Vect reflect(Ball ball, Vect velocity, double coefficient);

        /** The surface's own coefficient: an outer wall's is 1. */
        default double reflectionCoefficient() {
            return gizmo() == null ? 1.0 : gizmo().reflectionCoefficient();
        }

        @Override
        default TriggerSource struck() {
            return gizmo() == null ? TriggerSource.OUTER_WALLS : TriggerSource.gizmo(gizmo().name());
        }
    }

    /** A still surface that is a segment: it reflects as a wall, about the normal from its line. */
    sealed interface Flat extends StillSurface {
        LineSegment segment();

        @Override
        default Vect normal(Vect centre) {
            return fromLine(segment(), centre.x(), centre.y());
        }

        /** Reckoned from the ball's centre as coordinates: a bounce off a face makes no vector of it. */
        @Override
        default Vect normalTo(Ball ball) {
            return fromLine(segment(), ball.x() + 0.0, ball.y() + 0.0);   // ball.position()'s components
        }

        /** The wall reflection does not depend on where the ball is. */
        @Override
        default Vect reflect(Ball ball, Vect velocity, double coefficient) {
            return Geometry.reflectWall(segment(), velocity, coefficient);
        }
    }

    /** Outer wall {@code side} (0 top, 1 right, 2 bottom, 3 left). */
    record OuterWall(int side, LineSegment segment) implements Flat {
        @Override
        public GizmoBase gizmo() {
            return null;
        }

        @Override
        public ContactRef ref() {
            return ContactRef.Wall.of(side);
        }
    }

    /** Segment {@code index} of a still gizmo's shape: a side of a polygon bumper, an absorber or a still flipper. */
    record Face(GizmoBase gizmo, int index, LineSegment segment) implements Flat {
        @Override
        public ContactRef ref() {
            return new ContactRef.Part(gizmo.name(), false, index);
        }
    }

    /**
     * Circle {@code index} of a still gizmo's shape: a circle bumper, a zero-radius polygon corner, a still flipper's
     * round end, or a round end a moving shape turns in place.
     */
    record Round(GizmoBase gizmo, int index, Circle circle) implements StillSurface {
        @Override
        public ContactRef ref() {
            return new ContactRef.Part(gizmo.name(), true, index);
        }

        @Override
        public Vect normal(Vect centre) {
            return centre.minus(circle.getCenter()).unitSize();
        }

        @Override
        public Vect reflect(Ball ball, Vect velocity, double coefficient) {
            return Geometry.reflectCircle(circle.getCenter(), ball.position(), velocity, coefficient);
        }
    }

    /**
     * A part of a moving shape as it is now (a swinging flipper): side segment {@code index} or, when {@code circle},
     * circle {@code index} of its {@link MovingShape#shape()}.
     */
    record MovingPart(MovingShape shape, boolean circle, int index) implements Contact {
        @Override
        public TriggerSource struck() {
            return TriggerSource.gizmo(shape.name());
        }

        @Override
        public Vect normal(Vect centre) {
            return circle ? centre.minus(shape.shape().circles().get(index).getCenter()).unitSize()
                    : fromLine(shape.shape().segments().get(index), centre.x(), centre.y());
        }

        /** The speed is that of the surface where it touches the ball, turning about the pivot. */
        @Override
        public Squeeze.Side side(Vect centre, Function<Ball, Vect> motion) {
            Vect normal = normal(centre);
            Vect touching = centre.minus(normal.times(Arena.BALL_RADIUS));
            return new Squeeze.Side(normal,
                    Kinematics.surfaceVelocity(shape.pivot(), shape.angularVelocity(), touching).dot(normal));
        }

        /** The velocity {@code velocity} of the ball becomes when the part, turning, strikes it (physics-lib). */
        Vect reflect(Circle ball, Vect velocity) {
            Shape now = shape.shape();
            return circle
                    ? Geometry.reflectRotatingCircle(now.circles().get(index), shape.pivot(), shape.angularVelocity(),
                            ball, velocity, shape.reflectionCoefficient())
                    : Geometry.reflectRotatingWall(now.segments().get(index), shape.pivot(), shape.angularVelocity(),
                            ball, velocity, shape.reflectionCoefficient());
        }
    }

    record OtherBall(Ball other) implements Contact {
        @Override
        public Struck struck() {
            return other.asStruck();
        }

        @Override
        public Vect normal(Vect centre) {
            return centre.minus(other.position()).unitSize();
        }

        @Override
        public Squeeze.Side side(Vect centre, Function<Ball, Vect> motion) {
            Vect normal = normal(centre);
            return new Squeeze.Side(normal, motion.apply(other).dot(normal));
        }
    }

    /**
     * The unit normal from the line through a segment toward the point (x, y): {@code centre.minus(foot).unitSize()},
     * the foot {@code Geometry.perpendicularPointWholeLine}'s, reckoned on the components (the same doubles, in the
     * same order) so that only the normal is made.
     */
    private static Vect fromLine(LineSegment segment, double x, double y) {
        Vect p1 = segment.p1();
        Vect p2 = segment.p2();
        double dirX = p2.x() - p1.x() + 0.0;
        double dirY = p2.y() - p1.y() + 0.0;
        double footX = p1.x();
        double footY = p1.y();
        if (dirX != 0 || dirY != 0) {
            double along = ((x - p1.x() + 0.0) * dirX + (y - p1.y() + 0.0) * dirY) / (dirX * dirX + dirY * dirY);
            footX = p1.x() + (dirX * along + 0.0) + 0.0;
            footY = p1.y() + (dirY * along + 0.0) + 0.0;
        }
        return Components.unit(x - footX + 0.0, y - footY + 0.0);
    }
}
