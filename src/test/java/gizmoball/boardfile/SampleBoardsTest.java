package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.fail;

import gizmoball.model.Board;
import gizmoball.model.Invariants;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.GizmoKind;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The boards that ship in boards/: each loads strictly and plays 2,000 ticks with the invariants holding. */
class SampleBoardsTest {
    private static final Path BOARDS = Path.of("boards");

    @ParameterizedTest
    @ValueSource(strings = {"default.txt", "extensions.txt", "multiball.txt", "rube-goldberg.txt", "stress.txt"})
    void loadsStrictlyAndRunsWithTheInvariantsHolding(String name) throws IOException, BoardFileException {
        Board board = BoardFiles.load(BOARDS.resolve(name));
        assertThat(Invariants.violations(board)).isEmpty();
        for (int tick = 1; tick <= 2_000; tick++) {
            board.tick(Board.DEFAULT_TICK);
            List<String> violations = Invariants.violations(board);
            if (!violations.isEmpty()) {
                fail(name + " after tick " + tick + ": " + violations);
            }
        }
    }

    @Test
    void theDefaultBoardHasKeyedFlippersAKeyedAbsorberBumperTriggersAndABall() throws Exception {
        Board board = BoardFiles.load(BOARDS.resolve("default.txt"));
        assertThat(board.gizmos()).filteredOn(g -> g instanceof FlipperView).extracting(g -> g.name())
                .containsExactly("LF", "RF");
        assertThat(board.keyBindings()).extracting(k -> k.keyCode() + " " + k.edge() + " " + k.gizmo())
                .contains("90 DOWN LF", "90 UP LF", "47 DOWN RF", "47 UP RF", "32 DOWN A");
        assertThat(board.gizmo("A").orElseThrow().kind()).isEqualTo(GizmoKind.ABSORBER);
        assertThat(board.connections()).extracting(c -> c.target()).contains("LF", "RF");
        assertThat(board.balls()).hasSize(1);
    }

    @Test
    void theExtensionsBoardShowsOffTheSinksTheAcceleratorsAndTheWiringKit() throws Exception {
        Board board = BoardFiles.load(BOARDS.resolve("extensions.txt"));
        assertThat(board.gizmos()).extracting(g -> g.kind()).contains(GizmoKind.SINK, GizmoKind.ACCELERATOR,
                GizmoKind.SPAWNER, GizmoKind.DROP_TARGET, GizmoKind.PORTAL);
        assertThat(((gizmoball.model.gizmo.PortalView) board.gizmo("PL").orElseThrow()).pair()).contains("PR");
        assertThat(board.connections()).anyMatch(c -> c.order().delay() > 0 && c.order().action().isPresent());
        assertThat(board.keyBindings()).anyMatch(k -> k.order().delay() > 0);
        assertThat(board.gameRules().isGame()).isTrue();
    }

    @Test
    void theDefaultBoardRelaunchesItsBallOnSpace() throws Exception {
        Board board = BoardFiles.load(BOARDS.resolve("default.txt"));
        for (int tick = 0; tick < 120 && !board.balls().get(0).isCaptured(); tick++) {
            board.tick(Board.DEFAULT_TICK);
        }
        assertThat(board.balls().get(0).isCaptured()).as("the ball falls into the absorber").isTrue();
        board.keyDown(32);
        assertThat(board.balls().get(0).isCaptured()).isFalse();
        assertThat(board.balls().get(0).velocity().y()).isEqualTo(-Board.ABSORBER_LAUNCH_SPEED);
        assertThat(board.keyBindings()).anyMatch(k -> k.keyCode() == 32 && k.edge() == KeyEdge.DOWN);
    }

    @Test
    void theStressBoardHasThreeHundredGizmosAndTwentyBalls() throws Exception {
        Board board = BoardFiles.load(BOARDS.resolve("stress.txt"));
        assertThat(board.gizmos()).hasSizeGreaterThanOrEqualTo(300);
        assertThat(board.balls()).hasSize(20);
    }

    @Test
    void theRubeGoldbergBoardIsAChainOfTriggers() throws Exception {
        Board board = BoardFiles.load(BOARDS.resolve("rube-goldberg.txt"));
        assertThat(board.connections()).extracting(c -> c.source() + ">" + c.target())
                .contains("C1>A2", "S2>A3", "T3>A4", "A4>A4", "OuterWalls>F5");
    }
}
