package physics;

/**
 * The collision geometry behind the static {@link Geometry} facade. Times are in seconds and
 * {@code Double.POSITIVE_INFINITY} means "no collision" (for the rotating methods: none within the foresight
 * window). {@link GeometryImpl} documents the meaning of every method.
 */
public interface GeometryInterface {
    Geometry.DoublePair quadraticSolution(double a, double b, double c);

    double minQuadraticSolution(double a, double b, double c);

    Vect perpendicularPoint(LineSegment line, Vect point);

    Vect perpendicularPointWholeLine(LineSegment line, Vect point);

    Vect applyReflectionCoeff(Vect incidentVect, Vect reflectedVect, double reflectionCoeff);

    double timeUntilWallCollision(LineSegment line, Circle ball, Vect velocity);

    Vect reflectWall(LineSegment line, Vect velocity, double reflectionCoeff);

    Vect reflectWall(LineSegment line, Vect velocity);

    double distanceSquared(Vect v1, Vect v2);

    double distanceSquared(double x1, double y1, double x2, double y2);

    double timeUntilCircleCollision(Circle circle, Circle ball, Vect velocity);

    Vect reflectCircle(Vect circleCenter, Vect ballCenter, Vect ballVelocity, double reflectionCoeff);

    Vect reflectCircle(Vect circleCenter, Vect ballCenter, Vect ballVelocity);

    Vect rotateAround(Vect point, Vect centerOfRotation, Angle angle);

    LineSegment rotateAround(LineSegment line, Vect centerOfRotation, Angle angle);

    Circle rotateAround(Circle circle, Vect centerOfRotation, Angle angle);

    Geometry.DoublePair timeUntilCircleCollision(Circle circle, Vect point, Vect velocity);

    double timeUntilRotatingWallCollision(LineSegment line, Vect center, double angularVelocity, Circle ball,
                                          Vect velocity);

    Vect reflectRotatingWall(LineSegment line, Vect center, double angularVelocity, Circle ball, Vect velocity);

    Vect reflectRotatingWall(LineSegment line, Vect center, double angularVelocity, Circle ball, Vect velocity,
                             double reflectionCoeff);

    double timeUntilRotatingCircleCollision(Circle circle, Vect center, double angularVelocity, Circle ball,
                                            Vect velocity);

    Vect reflectRotatingCircle(Circle circle, Vect center, double angularVelocity, Circle ball, Vect velocity);

    Vect reflectRotatingCircle(Circle circle, Vect center, double angularVelocity, Circle ball, Vect velocity,
                               double reflectionCoeff);

    double timeUntilBallBallCollision(Circle ball1, Vect velocity1, Circle ball2, Vect velocity2);

    Geometry.VectPair reflectBalls(Vect center1, double mass1, Vect velocity1, Vect center2, double mass2,
                                   Vect velocity2);
}
