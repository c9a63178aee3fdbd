package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.Board;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import org.junit.jupiter.api.Test;
import physics.Vect;

/** Issue 23, item 9: between two ticks balls and flippers are drawn part of the way; the model is not touched. */
class InterpolationTest {
    private static final double DT = Board.DEFAULT_TICK;
    private final Board board = new Board();
    private final Interpolation between = new Interpolation();

    private BallView ball() {
        return board.balls().get(0);
    }

    private Vect tick() {
        Vect before = ball().position();
        board.tick(DT);
        between.ticked(board);
        return before;
    }

    @Test
    void aFlyingBallIsDrawnAsFarBetweenItsLastTwoPlacesAsRealTimeHasCome() {
        board.addBall("B", 10, 5, 3, 0);
        between.reset(board);
        Vect before = tick();
        Vect now = ball().position();

        between.setFraction(0.25);
        Vect drawn = between.ball(ball());

        assertThat(drawn.x()).isCloseTo(before.x() + 0.25 * (now.x() - before.x()), within(1e-12));
        assertThat(drawn.y()).isCloseTo(before.y() + 0.25 * (now.y() - before.y()), within(1e-12));
        assertThat(ball().position()).as("the model unchanged").isEqualTo(now);
        between.setFraction(1);
        assertThat(between.ball(ball())).isEqualTo(now);
    }

    @Test
    void afterAChangeOtherThanATickEverythingIsDrawnWhereItIs() {
        board.addBall("B", 10, 5, 3, 0);
        between.reset(board);
        tick();
        board.moveBall("B", 4, 4);
        between.reset(board);
        between.setFraction(0.5);

        assertThat(between.ball(ball())).isEqualTo(new Vect(4, 4));
    }

    @Test
    void aBallCaughtByAnAbsorberIsDrawnInItsCornerAtOnce() {
        board.addAbsorber("A", 0, 19, 20, 20);
        board.addBall("B", 10, 18.7, 0, 20);
        between.reset(board);
        while (!ball().isCaptured()) {
            tick();
        }
        between.setFraction(0.5);

        assertThat(between.ball(ball())).isEqualTo(ball().position());
    }

    @Test
    void aSwingingFlipperIsDrawnTurnedPartOfTheWayAboutItsPivot() {
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 5, 5);
        board.bindKey(90, gizmoball.model.KeyEdge.DOWN, "LF");
        between.reset(board);
        board.keyDown(90);
        FlipperView flipper = (FlipperView) board.gizmo("LF").orElseThrow();
        Vect restTip = flipper.tip();
        board.tick(DT);
        between.ticked(board);
        Vect pivot = flipper.pivot();

        between.setFraction(0.5);
        Vect drawn = between.tip(flipper);

        double restAngle = Math.atan2(restTip.y() - pivot.y(), restTip.x() - pivot.x());
        double nowAngle = Math.atan2(flipper.tip().y() - pivot.y(), flipper.tip().x() - pivot.x());
        double drawnAngle = Math.atan2(drawn.y() - pivot.y(), drawn.x() - pivot.x());
        assertThat(nowAngle).isNotEqualTo(restAngle);
        assertThat(drawnAngle).isCloseTo((restAngle + nowAngle) / 2, within(1e-9));
        assertThat(drawn.minus(pivot).length()).isCloseTo(flipper.tip().minus(pivot).length(), within(1e-12));
    }
}
