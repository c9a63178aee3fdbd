package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.DropTargetView;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.model.loop.BallView;
import org.junit.jupiter.api.Test;

/** The drop target: solid until a ball hits it, then nothing until raised, and never raised over a ball. */
class DropTargetTest {
    private static final double DT = Board.DEFAULT_TICK;
    private static final int RAISE = 82;

    private static Board board(double gravity) {
        Board board = new Board();
        board.setGravity(gravity);
        board.setFriction(0, 0);
        board.addGizmo(GizmoKind.DROP_TARGET, "T", 10, 10);
        board.bindKey(RAISE, KeyEdge.DOWN, "T", Order.of(Action.RAISE));
        return board;
    }

    private static DropTargetView target(Board board) {
        return (DropTargetView) board.gizmo("T").orElseThrow();
    }

    private static BallView ball(Board board, String name) {
        return board.ball(name).orElseThrow();
    }

    @Test
    void aBallBouncesOffTheTargetItHitsWhichIsDownAtTheEndOfThatTickAndTheBallFallsThroughItsCellAfter() {
        Board board = board(25);
        board.addBall("B", 10.5, 8, 0, 0);
        // Stage 1 before motion: after n ticks the ball has fallen g dt^2 n (n + 1) / 2; it reaches the target's top
        // (its centre at 9.75, 1.75 L down) in the tick where n (n + 1) first reaches 2 * 1.75 / (g dt^2) = 504: n = 22.
        for (int n = 1; n <= 21; n++) {
            board.tick(DT);
            assertThat(target(board).isDown()).as("up after tick " + n).isFalse();
        }
        board.tick(DT);
        assertThat(target(board).isDown()).as("down after the tick of the hit").isTrue();
        assertThat(ball(board, "B").velocity().y()).as("the ball bounced off it first").isNegative();
        assertThat(board.game().score()).as("a real hit scores a drop target's points").isEqualTo(100);
        for (int i = 0; i < 120 && ball(board, "B").position().y() < 11.5; i++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).isEmpty();
        }
        assertThat(ball(board, "B").position().y()).as("fallen through the empty cell").isGreaterThan(11.5);
    }

    @Test
    void raisedWithItsCellClearItIsUpAtOnceAndFallsAgainAtTheNextHit() {
        Board board = board(0);
        board.addBall("B", 10.5, 8.5, 0, 3);   // reaches the top (centre at 9.75) after 1.25 / 3 s: 25 ticks
        for (int i = 0; i < 26 && !target(board).isDown(); i++) {
            board.tick(DT);
        }
        assertThat(target(board).isDown()).isTrue();
        assertThat(ball(board, "B").velocity()).isEqualTo(new physics.Vect(0, -3));   // elastic, straight back
        board.keyDown(RAISE);
        assertThat(target(board).isDown()).as("the cell is clear: up at once").isFalse();
        board.setBallVelocity("B", 0, 3);
        for (int i = 0; i < 60 && !target(board).isDown(); i++) {
            board.tick(DT);
        }
        assertThat(target(board).isDown()).as("down again after the second hit").isTrue();
    }

    @Test
    void toldToRiseWhileABallIsInItsCellItWaitsDownUntilTheCellIsClearThenRises() {
        Board board = board(0);
        board.addBall("Hit", 10.5, 8.5, 0, 3);
        for (int i = 0; i < 26 && !target(board).isDown(); i++) {
            board.tick(DT);
        }
        assertThat(target(board).isDown()).isTrue();
        board.delete("Hit");   // it bounced back up; the ball that matters comes next
        board.addBall("B", 10.5, 9.2, 0, 3);   // drifting down through the empty cell at 3 L/s
        for (int i = 0; i < 20; i++) {
            board.tick(DT);   // 1/3 s: its centre at 10.2, inside the cell
        }
        board.keyDown(RAISE);
        assertThat(target(board).isDown()).as("a ball is in the cell").isTrue();
        assertThat(target(board).isRising()).isTrue();
        int ticks = 0;
        while (target(board).isDown()) {
            board.tick(DT);
            ticks++;
            assertThat(Invariants.violations(board)).isEmpty();
        }
        // Clear once the centre is r beyond the bottom edge (11.25): 1.05 L at 3 L/s = 0.35 s = 21 ticks.
        assertThat(ticks).isBetween(21, 22);
        assertThat(ball(board, "B").position().y()).isGreaterThan(11.25);
        assertThat(target(board).isRising()).isFalse();
    }

    @Test
    void aTargetSharesTheGatesRuleAndATriggerOfItsOwnRaisesIt() {
        assertThat(GizmoKind.DROP_TARGET.actions()).containsExactly(Action.RAISE, Action.FLASH);
        Board board = board(0);
        board.bindKey(84, KeyEdge.CHANGE, "T");   // a trigger: its default action, raise
        board.addBall("B", 10.5, 8.5, 0, 3);
        for (int i = 0; i < 26 && !target(board).isDown(); i++) {
            board.tick(DT);
        }
        board.keyDown(84);
        assertThat(target(board).isDown()).isFalse();
    }
}
