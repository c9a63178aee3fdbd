package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.Stage;
import gizmoball.model.loop.TickReport;

import org.junit.jupiter.api.Test;

/**
 * A tick times its stages only while asked (the physics overlay asks): off, every stage reads 0 and the game is the
 * same to the bit, for the clocks only watch it.
 */
class StageTimingTest {

    /** A ball bouncing among bumpers: collisions in most ticks, so every stage of the loop runs. */
    private static Board bouncing() throws BoardEditException {
        Board board = new Board();
        board.addGizmo(GizmoKind.CIRCLE, "C", 10, 10);
        board.addGizmo(GizmoKind.SQUARE, "S", 5, 12);
        board.addBall("B", 10.5, 3, 0, 20);
        return board;
    }

    private static long total(TickReport report) {
        return report.stageNanos().values().stream().mapToLong(Long::longValue).sum();
    }

    @Test
    void offByDefaultEveryStageReadsZero() throws BoardEditException {
        Board board = bouncing();
        long collisions = 0;
        for (int t = 0; t < 120; t++) {
            board.tick(Board.DEFAULT_TICK);
            assertThat(total(board.lastTick())).as("tick %d", t).isZero();
            collisions += board.lastTick().collisions();
        }
        assertThat(collisions).as("the ticks had collisions to time").isPositive();
    }

    @Test
    void onTheStagesAreTimedAndThePlayIsTheSame() throws BoardEditException {
        Board timed = bouncing();
        timed.setStageTiming(true);
        Board untimed = bouncing();
        long detection = 0;
        for (int t = 0; t < 120; t++) {
            timed.tick(Board.DEFAULT_TICK);
            untimed.tick(Board.DEFAULT_TICK);
            detection += timed.lastTick().stageNanos().get(Stage.COLLISION_DETECTION);
            assertThat(timed.balls().get(0).position()).as("tick %d", t)
                    .isEqualTo(untimed.balls().get(0).position());
            assertThat(timed.balls().get(0).velocity()).as("tick %d", t)
                    .isEqualTo(untimed.balls().get(0).velocity());
        }
        assertThat(detection).isPositive();
        timed.setStageTiming(false);
        timed.tick(Board.DEFAULT_TICK);
        assertThat(total(timed.lastTick())).isZero();
    }
}
