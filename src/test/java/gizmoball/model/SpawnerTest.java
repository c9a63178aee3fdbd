package gizmoball.model;

import gizmoball.model.gizmo.Setting;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.model.gizmo.Spawner;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.TriggerSource;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import physics.Vect;

/** The spawner: where its balls appear and how fast, and when it adds none. */
class SpawnerTest {
    private static final int KEY = 83;

    private static Board boardWithSpawner(int turns) {
        Board board = new Board();
        board.addGizmo(GizmoKind.SPAWNER, "SP", 8, 8);
        for (int i = 0; i < turns; i++) {
            board.rotate("SP");
        }
        board.bindKey(KEY, KeyEdge.DOWN, "SP");
        return board;
    }

    @ParameterizedTest(name = "{0} quarter turns: the mouth at ({1}, {2})")
    @CsvSource({"0, 8.5, 7.75", "1, 9.25, 8.5", "2, 8.5, 9.25", "3, 7.75, 8.5"})
    void aBallAppearsTouchingTheSideItFacesWithTheAuthorsVelocity(int turns, double x, double y) {
        Board board = boardWithSpawner(turns);
        board.set("SP", new Setting.Launch(3, -4));
        board.keyDown(KEY);
        assertThat(board.balls()).hasSize(1);
        BallView ball = board.balls().get(0);
        assertThat(ball.position()).isEqualTo(new Vect(x, y));
        assertThat(ball.velocity()).isEqualTo(new Vect(3, -4));
        assertThat(ball.name()).isEqualTo("Ball1");
        assertThat(board.lastTick().events()).isEmpty();   // reported with the next tick, as key actions are
        board.tick(Board.DEFAULT_TICK);
        assertThat(board.lastTick().events()).contains(new PlayEvent.Spawned("SP", "Ball1"));
    }

    @Test
    void aMouthThatIsNotFreeSpawnsNothing() {
        Board board = boardWithSpawner(0);
        board.addBall("B", 8.5, 7.5, 0, 0);   // over the mouth
        board.keyDown(KEY);
        assertThat(board.balls()).hasSize(1);
        Board walled = boardWithSpawner(0);
        walled.addGizmo(GizmoKind.SQUARE, "S", 8, 7);
        walled.keyDown(KEY);
        assertThat(walled.balls()).isEmpty();
        Board edge = new Board();
        edge.addGizmo(GizmoKind.SPAWNER, "SP", 3, 0);
        edge.trigger("SP");
        assertThat(edge.balls()).as("a mouth off the board").isEmpty();
    }

    @Test
    void aBoardOf200BallsGetsNoMore() {
        Board board = boardWithSpawner(0);
        int n = 0;
        for (int y : new int[] {0, 1, 12, 13, 14, 15, 16, 17, 18, 19}) {   // 10 rows of 20, clear of the mouth
            for (int x = 0; x < 20; x++) {
                board.addBall("F" + n++, x + 0.5, y + 0.5, 0, 0);
            }
        }
        assertThat(board.balls()).hasSize(Spawner.MAX_BALLS);
        board.keyDown(KEY);
        assertThat(board.balls()).hasSize(Spawner.MAX_BALLS);
        board.delete("F0");
        board.keyDown(KEY);
        assertThat(board.balls()).hasSize(Spawner.MAX_BALLS);
    }

    @Test
    void aHitThatSpawnsAddsTheBallAtTheEndOfThatTickAndADelayedSpawnWaits() {
        Board board = boardWithSpawner(0);
        board.addGizmo(GizmoKind.SQUARE, "S", 2, 10);
        board.addBall("Drop", 2.5, 9.6, 0, 10);   // 0.15 L above the square: it hits after 0.015 s
        board.connect(TriggerSource.gizmo("S"), "SP");
        board.tick(Board.DEFAULT_TICK);   // the ball touches the square within this tick
        assertThat(board.ball("Ball1")).as("spawned once the tick was over").isPresent();
        board.unbindKey(KEY, KeyEdge.DOWN, "SP");
        board.bindKey(KEY, KeyEdge.DOWN, "SP", Order.of(Action.SPAWN).after(0.05));
        board.moveBall("Ball1", 15.5, 2);
        board.keyDown(KEY);
        assertThat(board.ball("Ball2")).isEmpty();
        for (int i = 0; i < 4; i++) {
            board.tick(Board.DEFAULT_TICK);
        }
        assertThat(board.ball("Ball2")).as("3 ticks = 0.05 s: spawned before the fourth").isPresent();
    }

    @Test
    void theVelocityIsFiniteAndWithinTheSpeedLimitAndOnlyASpawnersOwn() {
        Board board = boardWithSpawner(0);
        board.addGizmo(GizmoKind.SQUARE, "S", 1, 1);
        assertThatThrownBy(() -> board.set("SP", new Setting.Launch(300, 0))).isInstanceOf(BoardEditException.class)
                .hasMessageStartingWith("a spawner's velocity is finite and at most 200 L/s");
        assertThatThrownBy(() -> board.set("SP", new Setting.Launch(Double.NaN, 0))).isInstanceOf(BoardEditException.class);
        assertThatThrownBy(() -> board.set("S", new Setting.Launch(1, 0)))
                .hasMessage("only a spawner has a velocity for its balls: S is a square");
    }
}
