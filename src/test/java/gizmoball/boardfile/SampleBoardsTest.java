package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.fail;

import gizmoball.model.Board;
import gizmoball.model.Invariants;
import gizmoball.model.gizmo.AbsorberView;
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
    @ValueSource(strings = {"default.txt", "arcade.txt", "orbit.txt", "castle.txt", "extensions.txt", "multiball.txt",
        "rube-goldberg.txt", "stress.txt"})
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
    void theDefaultBoardHasKeyedFlippersAPlungerUnderItsLaneADrainAndABall() throws Exception {
        Board board = BoardFiles.load(BOARDS.resolve("default.txt"));
        assertThat(board.gizmos()).filteredOn(g -> g instanceof FlipperView).extracting(g -> g.name())
                .containsExactly("LF", "RF");
        assertThat(board.keyBindings()).extracting(k -> k.keyCode() + " " + k.edge() + " " + k.gizmo())
                .contains("90 DOWN LF", "90 UP LF", "47 DOWN RF", "47 UP RF", "32 DOWN Drain", "32 DOWN Plunger");
        assertThat(board.gizmo("Drain").orElseThrow().kind()).isEqualTo(GizmoKind.ABSORBER);
        assertThat(board.gameRules().isDrain("Drain")).isTrue();
        assertThat(((AbsorberView) board.gizmo("Plunger").orElseThrow()).plunger()).isPresent();
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
        assertThat(board.gameRules().isGame()).as("a sandbox").isFalse();
    }

    @Test
    void theDefaultBoardServesItsBallToThePlungerOnSpaceAndTheReleaseLaunchesIt() throws Exception {
        Board board = BoardFiles.load(BOARDS.resolve("default.txt"));
        AbsorberView plunger = (AbsorberView) board.gizmo("Plunger").orElseThrow();
        board.keyDown(32);
        for (int tick = 0; tick < 60 && plunger.held().isEmpty(); tick++) {
            board.tick(Board.DEFAULT_TICK);
        }
        assertThat(plunger.held()).as("the drained ball goes up into the plunger").containsExactly("B");
        for (int tick = 0; tick < 120; tick++) {
            board.tick(Board.DEFAULT_TICK);
        }
        board.keyUp(32);
        assertThat(board.balls().get(0).isCaptured()).isFalse();
        assertThat(board.balls().get(0).velocity().y()).as("a full pull")
                .isEqualTo(-plunger.plunger().orElseThrow().fullSpeed());
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
