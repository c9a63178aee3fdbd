package physics;

import java.io.Serializable;

/**
 * Static facade over a {@link GeometryInterface}; by default a stateless {@link GeometryImpl} with the default
 * foresight. Prefer an own {@code GeometryImpl} instance for any tuning: {@link #setGeometry},
 * {@link #setForesight} and {@link #setTuningParameters} exist for API compatibility and change the facade for
 * the whole JVM. {@code Geometry.setGeometry(new GeometryImpl())} restores the default.
 */
public class Geometry {
    /** The "no solution" answer of {@link #quadraticSolution} and {@link #timeUntilCircleCollision(Circle, Vect, Vect)}. */
    public static final DoublePair DOUBLE_PAIR_NAN = new DoublePair(Double.NaN);

    private static volatile GeometryInterface geometry = new GeometryImpl();

    private Geometry() {
    }

    public static void setGeometry(GeometryInterface newGeometry) {
        if (newGeometry == null) {
            throw new IllegalArgumentException("geometry must not be null");
        }
        geometry = newGeometry;
    }

    /** Installs {@code new GeometryImpl(maximumForesight, GeometryImpl.DEFAULT_SEARCH_SLICES)}. */
    public static void setForesight(double maximumForesight) {
        setGeometry(new GeometryImpl(maximumForesight, GeometryImpl.DEFAULT_SEARCH_SLICES));
    }

    /**
     * Installs {@code new GeometryImpl(maximumForesight, numberOfSlices)}. {@code useDoughnut} is accepted for
     * API compatibility and has no effect: the rotating search needs no doughnut pre-filter to be exact.
     */
    public static void setTuningParameters(double maximumForesight, boolean useDoughnut, int numberOfSlices) {
        setGeometry(new GeometryImpl(maximumForesight, numberOfSlices));
    }

    public static DoublePair quadraticSolution(double a, double b, double c) {
        return geometry.quadraticSolution(a, b, c);
    }

    public static double minQuadraticSolution(double a, double b, double c) {
        return geometry.minQuadraticSolution(a, b, c);
    }

    public static Vect perpendicularPoint(LineSegment line, Vect point) {
        return geometry.perpendicularPoint(line, point);
    }

    public static Vect perpendicularPointWholeLine(LineSegment line, Vect point) {
        return geometry.perpendicularPointWholeLine(line, point);
    }

    public static Vect applyReflectionCoeff(Vect incidentVect, Vect reflectedVect, double reflectionCoeff) {
        return geometry.applyReflectionCoeff(incidentVect, reflectedVect, reflectionCoeff);
    }

    public static double timeUntilWallCollision(LineSegment line, Circle ball, Vect velocity) {
        return geometry.timeUntilWallCollision(line, ball, velocity);
    }

    public static Vect reflectWall(LineSegment line, Vect velocity, double reflectionCoeff) {
        return geometry.reflectWall(line, velocity, reflectionCoeff);
    }

    public static Vect reflectWall(LineSegment line, Vect velocity) {
        return geometry.reflectWall(line, velocity);
    }

    public static double distanceSquared(Vect v1, Vect v2) {
        return geometry.distanceSquared(v1, v2);
    }

    public static double distanceSquared(double x1, double y1, double x2, double y2) {
        return geometry.distanceSquared(x1, y1, x2, y2);
    }

    public static double timeUntilCircleCollision(Circle circle, Circle ball, Vect velocity) {
        return geometry.timeUntilCircleCollision(circle, ball, velocity);
    }

    public static Vect reflectCircle(Vect circleCenter, Vect ballCenter, Vect ballVelocity, double reflectionCoeff) {
        return geometry.reflectCircle(circleCenter, ballCenter, ballVelocity, reflectionCoeff);
    }

    public static Vect reflectCircle(Vect circleCenter, Vect ballCenter, Vect ballVelocity) {
        return geometry.reflectCircle(circleCenter, ballCenter, ballVelocity);
    }

    public static Vect rotateAround(Vect point, Vect centerOfRotation, Angle angle) {
        return geometry.rotateAround(point, centerOfRotation, angle);
    }

    public static LineSegment rotateAround(LineSegment line, Vect centerOfRotation, Angle angle) {
        return geometry.rotateAround(line, centerOfRotation, angle);
    }

    public static Circle rotateAround(Circle circle, Vect centerOfRotation, Angle angle) {
        return geometry.rotateAround(circle, centerOfRotation, angle);
    }

    public static DoublePair timeUntilCircleCollision(Circle circle, Vect point, Vect velocity) {
        return geometry.timeUntilCircleCollision(circle, point, velocity);
    }

    public static double timeUntilRotatingWallCollision(LineSegment line, Vect center, double angularVelocity,
                                                        Circle ball, Vect velocity) {
        return geometry.timeUntilRotatingWallCollision(line, center, angularVelocity, ball, velocity);
    }

    public static Vect reflectRotatingWall(LineSegment line, Vect center, double angularVelocity, Circle ball,
                                           Vect velocity) {
        return geometry.reflectRotatingWall(line, center, angularVelocity, ball, velocity);
    }

    public static Vect reflectRotatingWall(LineSegment line, Vect center, double angularVelocity, Circle ball,
                                           Vect velocity, double reflectionCoeff) {
        return geometry.reflectRotatingWall(line, center, angularVelocity, ball, velocity, reflectionCoeff);
    }

    public static double timeUntilRotatingCircleCollision(Circle circle, Vect center, double angularVelocity,
                                                          Circle ball, Vect velocity) {
        return geometry.timeUntilRotatingCircleCollision(circle, center, angularVelocity, ball, velocity);
    }

    public static Vect reflectRotatingCircle(Circle circle, Vect center, double angularVelocity, Circle ball,
                                             Vect velocity) {
        return geometry.reflectRotatingCircle(circle, center, angularVelocity, ball, velocity);
    }

    public static Vect reflectRotatingCircle(Circle circle, Vect center, double angularVelocity, Circle ball,
                                             Vect velocity, double reflectionCoeff) {
        return geometry.reflectRotatingCircle(circle, center, angularVelocity, ball, velocity, reflectionCoeff);
    }

    public static double timeUntilBallBallCollision(Circle ball1, Vect velocity1, Circle ball2, Vect velocity2) {
        return geometry.timeUntilBallBallCollision(ball1, velocity1, ball2, velocity2);
    }

    public static VectPair reflectBalls(Vect center1, double mass1, Vect velocity1, Vect center2, double mass2,
                                        Vect velocity2) {
        return geometry.reflectBalls(center1, mass1, velocity1, center2, mass2, velocity2);
    }

    /** An immutable pair of vectors, e.g. the two velocities after a ball-ball collision. */
    public static class VectPair implements Serializable {
        private static final long serialVersionUID = 1L;

        public final Vect v1;
        public final Vect v2;

        public VectPair(Vect v1, Vect v2) {
            this.v1 = v1;
            this.v2 = v2;
        }

        public boolean equals(VectPair other) {
            return other != null && v1.equals(other.v1) && v2.equals(other.v2);
        }

        @Override
        public boolean equals(Object other) {
            return other instanceof VectPair p && equals(p);
        }

        @Override
        public int hashCode() {
            return 31 * v1.hashCode() + v2.hashCode();
        }

        @Override
        public String toString() {
            return "[" + v1 + "," + v2 + "]";
        }
    }

    /**
     * An immutable pair of numbers, e.g. the two roots of a quadratic (d1 &le; d2). NaN marks "no value";
     * equality treats NaN as equal to NaN and 0.0 as equal to -0.0, consistently with hashCode.
     */
    public static class DoublePair implements Serializable {
        private static final long serialVersionUID = 1L;

        public final double d1;
        public final double d2;

        public DoublePair(double d1, double d2) {
            this.d1 = d1 + 0.0;
            this.d2 = d2 + 0.0;
        }

        /** A pair with both values equal. */
        public DoublePair(double d) {
            this(d, d);
        }

        /** @return whether both values are finite (neither NaN nor infinite) */
        public boolean areFinite() {
            return Double.isFinite(d1) && Double.isFinite(d2);
        }

        public boolean equals(DoublePair other) {
            // Double.compare treats NaN as equal to itself; the constructor already removed -0.0.
            return other != null && Double.compare(d1, other.d1) == 0 && Double.compare(d2, other.d2) == 0;
        }

        @Override
        public boolean equals(Object other) {
            return other instanceof DoublePair p && equals(p);
        }

        @Override
        public int hashCode() {
            return 31 * Double.hashCode(d1) + Double.hashCode(d2);
        }

        @Override
        public String toString() {
            return "[" + d1 + "," + d2 + "]";
        }
    }
}
