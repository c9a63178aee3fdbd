package gizmoball.model.loop;

import gizmoball.model.Board;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import physics.Vect;

/**
 * The velocity a squeezed ball leaves with (docs/design.md, "Pinched balls"): the nearest to the one it has that
 * leaves every side, each side a half-plane of velocities; none when the half-planes meet only beyond
 * {@link Board#MAX_SPEED} or not at all.
 */
class SqueezeTest {
    private static final double EXACT = 1e-12;
    /** A still floor under the ball: it must not move down (+y). */
    private static final Squeeze.Side FLOOR = new Squeeze.Side(new Vect(0, -1), 0);
    /** A still wall to the ball's right: it must not move right. */
    private static final Squeeze.Side WALL_RIGHT = new Squeeze.Side(new Vect(-1, 0), 0);

    private static void assertVect(Vect actual, double x, double y) {
        assertThat(actual.x()).isCloseTo(x, within(EXACT));
        assertThat(actual.y()).isCloseTo(y, within(EXACT));
    }

    @Test
    void aVelocityThatLeavesEverySideIsKept() {
        Squeeze.Side pushing = new Squeeze.Side(new Vect(1, 0), 5);
        assertVect(Squeeze.leaving(new Vect(7, -2), List.of(pushing, FLOOR)).orElseThrow(), 7, -2);
    }

    /** Into the floor but fast enough off the flipper: only the part into the floor goes. */
    @Test
    void aVelocityBreakingOneSideIsProjectedOntoItsEdge() {
        Squeeze.Side pushing = new Squeeze.Side(new Vect(1, 0), 5);
        assertVect(Squeeze.leaving(new Vect(7, 3), List.of(pushing, FLOOR)).orElseThrow(), 7, 0);
    }

    /** Too slow off the flipper and into the floor: the corner, v . (1, 0) = 5 on the floor's edge. */
    @Test
    void aVelocityBreakingBothSidesGoesToTheirCorner() {
        Squeeze.Side pushing = new Squeeze.Side(new Vect(1, 0), 5);
        assertVect(Squeeze.leaving(new Vect(3, 2), List.of(pushing, FLOOR)).orElseThrow(), 5, 0);
    }

    /**
     * A flipper pushing at s along n = (cos b, -sin b) towards a wall on the right: the slowest way out runs along
     * the wall, (0, -s / sin b), s / sqrt(1 - (n . wall)^2) fast: the tighter the angle, the faster.
     */
    @ParameterizedTest(name = "{0} degrees from the wall's normal")
    @ValueSource(doubles = {30, 60, 80})
    void theSlowestWayOutOfAWedgeRunsAlongTheWall(double degrees) {
        double b = Math.toRadians(degrees);
        double s = 10;
        Squeeze.Side pushing = new Squeeze.Side(new Vect(Math.cos(b), -Math.sin(b)), s);
        Vect out = Squeeze.leaving(Vect.ZERO, List.of(pushing, WALL_RIGHT)).orElseThrow();
        assertVect(out, 0, -s / Math.sin(b));
    }

    @Test
    void surfacesFacingEachOtherSquarelyJamTheBall() {
        Squeeze.Side pushing = new Squeeze.Side(new Vect(1, 0), 5);
        assertThat(Squeeze.leaving(new Vect(-3, 1), List.of(pushing, WALL_RIGHT))).isEmpty();
    }

    /** Out at 1 degree, s / sin(1 degree) = 57 s: for s = 5 that is beyond MAX_SPEED, a jam. */
    @Test
    void aWayOutFasterThanTheSpeedLimitIsNoWayOut() {
        double b = Math.toRadians(1);
        assertThat(5 / Math.sin(b)).isGreaterThan(Board.MAX_SPEED);
        Squeeze.Side pushing = new Squeeze.Side(new Vect(Math.cos(b), -Math.sin(b)), 5);
        assertThat(Squeeze.leaving(new Vect(-3, 0), List.of(pushing, WALL_RIGHT))).isEmpty();
        Squeeze.Side slower = new Squeeze.Side(pushing.normal(), 3);
        assertThat(3 / Math.sin(b)).isLessThan(Board.MAX_SPEED);
        assertThat(Squeeze.leaving(new Vect(-3, 0), List.of(slower, WALL_RIGHT))).isPresent();
    }

    /** A pocket: floor, wall on the right, and a flipper pushing down and right: nothing leaves all three. */
    @Test
    void aPocketTheFlipperClosesJamsTheBall() {
        Squeeze.Side pushing = new Squeeze.Side(new Vect(0.6, 0.8), 4);
        assertThat(Squeeze.leaving(new Vect(-1, -1), List.of(pushing, FLOOR, WALL_RIGHT))).isEmpty();
    }
}
