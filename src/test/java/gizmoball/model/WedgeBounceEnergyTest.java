package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import physics.Vect;

/**
 * A ball dropped without friction into the wedge between a circle and a triangle's slope (docs/design.md, "Energy
 * drift"): where it meets both sides at once early in a tick, the bounces' timing moves the shadow energy
 * S = |v + g dt/2|^2/2 - g . p by (s - 1/2) dt g . dv, more than a correction along the last bounce's normal can take
 * back; the ball's w = v + g dt/2 is then scaled instead. Coming to rest in the wedge may lose energy; nothing may
 * gain it. Before, these drops gained 0.35 and 0.46.
 */
class WedgeBounceEnergyTest {
    private static final double DT = Board.DEFAULT_TICK;

    @ParameterizedTest
    @CsvSource({"7.93, 10.7", "7.97, 10.7"})
    void aBallBouncingInAWedgeNeverGainsShadowEnergy(double x, double y) {
        Board board = new Board();
        board.setFriction(0, 0);
        board.addGizmo(GizmoKind.TRIANGLE, "T", 8, 11);   // its slope from (8, 12) up to (9, 11)
        board.addGizmo(GizmoKind.CIRCLE, "C", 7, 11);
        board.addBall("B", x, y, 0, 0);
        double start = shadowEnergy(board);
        for (int i = 0; i < 60 * 60; i++) {
            board.tick(DT);
            assertThat(shadowEnergy(board)).as("tick %d", i).isLessThanOrEqualTo(start + 1e-9 * Math.abs(start));
        }
    }

    private static double shadowEnergy(Board board) {
        BallView ball = board.ball("B").orElseThrow();
        Vect g = new Vect(0, board.gravity());
        Vect w = ball.velocity().plus(g.times(DT / 2));
        return w.dot(w) / 2 - g.dot(ball.position());
    }
}
