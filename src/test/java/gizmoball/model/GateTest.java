package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.GateView;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import org.junit.jupiter.api.Test;

/** The gate: solid while closed, nothing while open, and never closed over a ball. */
class GateTest {
    private static final double DT = Board.DEFAULT_TICK;
    private static final int OPEN = 79;
    private static final int CLOSE = 67;

    private static Board board() {
        Board board = new Board();
        board.addGizmo(GizmoKind.GATE, "G", 10, 10);
        board.bindKey(OPEN, KeyEdge.DOWN, "G", Order.of(Action.OPEN));
        board.bindKey(CLOSE, KeyEdge.DOWN, "G", Order.of(Action.CLOSE));
        return board;
    }

    private static GateView gate(Board board) {
        return (GateView) board.gizmo("G").orElseThrow();
    }

    @Test
    void aClosedGateHoldsABallUpAndAnOpenOneLetsItFallThrough() {
        Board board = board();
        board.addBall("B", 10.5, 9.75, 0, 0);   // lying on the closed gate
        for (int i = 0; i < 30; i++) {
            board.tick(DT);
        }
        assertThat(board.ball("B").orElseThrow().position().y()).isLessThanOrEqualTo(9.75 + 1e-9);
        board.keyDown(OPEN);
        assertThat(gate(board).isOpen()).isTrue();
        for (int i = 0; i < 30; i++) {
            board.tick(DT);
        }
        assertThat(board.ball("B").orElseThrow().position().y()).as("fallen through the open gate").isGreaterThan(11);
        assertThat(Invariants.violations(board)).isEmpty();
    }

    /** A gate that switches changes the board at its cell only: a ball asleep elsewhere sleeps on (design.md). */
    @Test
    void aGateThatOpensAndClosesLeavesABallAsleepElsewhereAsleep() {
        Board board = board();
        board.addBall("B", 2.5, 19.75, 0, 0);   // on the floor, far from the gate
        for (int i = 0; i < 60; i++) {
            board.tick(DT);
        }
        assertThat(board.ball("B").orElseThrow().isAsleep()).as("settled on the floor").isTrue();
        for (int i = 0; i < 10; i++) {
            board.keyDown(i % 2 == 0 ? OPEN : CLOSE);
            board.tick(DT);
            assertThat(gate(board).isOpen()).isEqualTo(i % 2 == 0);
            assertThat(board.ball("B").orElseThrow().isAsleep()).as("asleep after switch %d", i).isTrue();
        }
        assertThat(board.ball("B").orElseThrow().position().y()).isEqualTo(19.75);
    }

    /** What rests on a ball lying on the gate goes with it when the gate opens: waking spreads along contacts. */
    @Test
    void anOpeningGateDropsTheBallOnItAndTheBallRestingOnThatBall() {
        Board board = board();
        board.addBall("Low", 10.5, 9.75, 0, 0);   // lying on the closed gate
        board.addBall("High", 10.5, 9.25, 0, 0);  // lying on Low
        for (int i = 0; i < 60; i++) {
            board.tick(DT);
        }
        assertThat(board.ball("High").orElseThrow().isAsleep()).as("the stack settled").isTrue();
        board.keyDown(OPEN);
        for (int i = 0; i < 30; i++) {
            board.tick(DT);
            assertThat(Invariants.violations(board)).isEmpty();
        }
        assertThat(board.ball("Low").orElseThrow().position().y()).as("fallen through the open gate").isGreaterThan(11);
        assertThat(board.ball("High").orElseThrow().position().y()).as("fallen after it").isGreaterThan(10.5);
    }

    @Test
    void aGateToldToCloseOverABallWaitsOpenUntilTheCellIsClearThenCloses() {
        Board board = new Board();
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addGizmo(GizmoKind.GATE, "G", 10, 10);
        board.bindKey(OPEN, KeyEdge.DOWN, "G", Order.of(Action.OPEN));
        board.bindKey(CLOSE, KeyEdge.DOWN, "G", Order.of(Action.CLOSE));
        board.keyDown(OPEN);
        board.addBall("B", 10.5, 9.2, 0, 3);   // drifting down through the open cell at 3 L/s
        for (int i = 0; i < 20; i++) {
            board.tick(DT);   // 1/3 s: its centre at 10.2, inside the cell
        }
        board.keyDown(CLOSE);
        assertThat(gate(board).isOpen()).as("a ball is in the cell").isTrue();
        assertThat(gate(board).isClosing()).isTrue();
        int ticks = 0;
        while (gate(board).isOpen()) {
            board.tick(DT);
            ticks++;
            assertThat(Invariants.violations(board)).isEmpty();
        }
        // Clear once the centre is r beyond the bottom edge (11.25): 1.05 L at 3 L/s = 0.35 s = 21 ticks.
        assertThat(ticks).isBetween(21, 22);
        assertThat(board.ball("B").orElseThrow().position().y()).isGreaterThan(11.25);
    }

    @Test
    void toggleOpensAClosedGateClosesAnOpenOneAndCancelsAWaitingClose() {
        Board board = board();
        board.bindKey(84, KeyEdge.CHANGE, "G");   // a trigger: its own action, toggle
        board.keyDown(84);
        assertThat(gate(board).isOpen()).isTrue();
        board.keyDown(84);
        assertThat(gate(board).isOpen()).isFalse();
        board.keyDown(OPEN);
        board.addBall("B", 10.5, 10.5, 0, 0);
        board.keyDown(CLOSE);
        assertThat(gate(board).isClosing()).isTrue();
        board.keyDown(84);
        assertThat(gate(board).isOpen()).isTrue();
        assertThat(gate(board).isClosing()).as("the toggle keeps it open").isFalse();
    }
}
