package gizmoball.fuzz;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.Invariants;
import gizmoball.model.gizmo.Flipper;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.LongStream;

import org.junit.jupiter.api.Test;

/**
 * The generator's boards are legal boards (what the board's editing operations accept, every one saved and loaded
 * again unchanged, none breaking a rule before play), the same for the same seed, and as broad as issue 20 asks:
 * every kind in every rotation, flippers next to each other and to bumpers, absorbers firing themselves, 5-40 balls
 * up to 100 L/s touching gizmos, flippers and each other, key scripts, and boards keeping energy.
 */
class DenseBoardsTest {
    private static final int TICKS = 600;
    /** Never played: the tests that play generate their own. */
    private static final List<FuzzCase> CASES = LongStream.range(0, 120).mapToObj(s -> DenseBoards.generate(s, TICKS))
            .toList();

    @Test
    void theSameSeedGivesTheSameBoardAndScript() {
        for (long seed : new long[] {0, 7, 123_456_789}) {
            FuzzCase a = DenseBoards.generate(seed, TICKS);
            FuzzCase b = DenseBoards.generate(seed, TICKS);
            assertThat(BoardFiles.toText(b.board())).isEqualTo(BoardFiles.toText(a.board()));
            assertThat(b.keys()).isEqualTo(a.keys());
            assertThat(b.recipe()).isEqualTo(a.recipe());
        }
        assertThat(BoardFiles.toText(CASES.get(1).board())).isNotEqualTo(BoardFiles.toText(CASES.get(2).board()));
    }

    @Test
    void everyBoardIsLegalLoadsAgainUnchangedAndBreaksNoRuleBeforePlay() throws Exception {
        for (FuzzCase c : CASES) {
            String text = BoardFiles.toText(c.board());
            assertThat(BoardFiles.toText(BoardFiles.load("seed " + c.seed(), text))).as("seed %d", c.seed())
                    .isEqualTo(text);
            assertThat(Invariants.violations(c.board())).as("seed %d", c.seed()).isEmpty();
            assertThat(new TickChecker(c.board()).check(c.board(), 0)).as("seed %d", c.seed()).isEmpty();
            long balls = c.board().balls().size();
            assertThat(balls).as("seed %d", c.seed()).isBetween(5L, 40L);
            for (BallView ball : c.board().balls()) {
                assertThat(ball.velocity().length()).as("seed %d %s", c.seed(), ball).isLessThanOrEqualTo(BallPlacer.MAX_SPEED);
            }
        }
    }

    /** The reproduction file of a case plays exactly as the case itself: a failing board can be replayed. */
    @Test
    void aCaseWrittenAsAReproductionPlaysTheSame() throws Exception {
        for (long seed = 0; seed < 6; seed++) {
            FuzzCase c = DenseBoards.generate(seed, TICKS);
            Reproduction written = Reproduction.parse("seed " + c.seed(), c.reproduction().toText());
            assertThat(written.ticks()).isEqualTo(c.ticks());
            assertThat(written.keys()).isEqualTo(c.keys());
            Board replayed = written.load("seed " + c.seed());
            FuzzPlay.play(replayed, written.keys(), 200, FuzzPlay.UNTIMED);
            FuzzPlay.play(c.board(), c.keys(), 200, FuzzPlay.UNTIMED);
            assertThat(BoardFiles.toText(replayed)).as("seed %d", c.seed()).isEqualTo(BoardFiles.toText(c.board()));
        }
    }

    @Test
    void theBoardsCoverEveryKindInEveryRotationWithFlippersPackedAndAbsorbersFiringThemselves() {
        Set<String> kindsAndTurns = new HashSet<>();
        int flipperNeighbours = 0;
        int selfFiring = 0;
        int energyKept = 0;
        int weightless = 0;
        int frictionless = 0;
        int startedSwinging = 0;
        int heavy = 0;
        int upsideDown = 0;
        int spinners = 0;
        int wallFed = 0;
        for (FuzzCase c : CASES) {
            Board board = c.board();
            for (Gizmo g : board.gizmos()) {
                kindsAndTurns.add(g.kind() + " " + g.rotation());
                if (g instanceof Flipper f) {
                    flipperNeighbours += touchesAnother(board, f) ? 1 : 0;
                    startedSwinging += f.angleFromRest() > 0 ? 1 : 0;
                }
                spinners += g.kind() == GizmoKind.SPINNER ? 1 : 0;
            }
            for (Connection connection : board.connections()) {
                selfFiring += connection.source().equals(TriggerSource.gizmo(connection.target())) ? 1 : 0;
                wallFed += connection.source().equals(TriggerSource.OUTER_WALLS)
                        && connection.target().startsWith("SP") ? 1 : 0;
            }
            energyKept += new TickChecker(board).checksEnergy() ? 1 : 0;
            weightless += board.gravity() == 0 ? 1 : 0;
            heavy += board.gravity() > 80 ? 1 : 0;
            upsideDown += board.gravity() < 0 ? 1 : 0;
            frictionless += board.mu() == 0 && board.mu2() == 0 ? 1 : 0;
        }
        for (GizmoKind kind : List.of(GizmoKind.SQUARE, GizmoKind.TRIANGLE, GizmoKind.LEFT_FLIPPER,
                GizmoKind.RIGHT_FLIPPER)) {
            for (int turns = 0; turns < 4; turns++) {
                assertThat(kindsAndTurns).contains(kind + " " + turns);
            }
        }
        assertThat(kindsAndTurns).contains("CIRCLE 0", "ABSORBER 0", "SINK 0", "ACCELERATOR 0", "SPINNER 0", "GATE 0",
                "DROP_TARGET 0");
        for (GizmoKind kind : List.of(GizmoKind.SPAWNER, GizmoKind.PORTAL)) {
            for (int turns = 0; turns < 4; turns++) {
                assertThat(kindsAndTurns).contains(kind + " " + turns);
            }
        }
        assertThat(wallFed).as("spawners fed by the outer walls").isGreaterThan(5);
        assertThat(spinners).as("spinners").isGreaterThan(20);
        assertThat(flipperNeighbours).as("flippers next to other gizmos").isGreaterThan(100);
        assertThat(selfFiring).as("absorbers firing themselves").isGreaterThan(30);
        assertThat(energyKept).as("boards keeping energy").isBetween(8, 40);
        assertThat(weightless).isGreaterThan(energyKept);
        assertThat(frictionless).isGreaterThan(energyKept);
        assertThat(startedSwinging).as("flippers starting part-way").isGreaterThan(10);
        assertThat(heavy).as("gravity over 80 L/s^2").isPositive();
        assertThat(upsideDown).as("gravity pointing up").isPositive();
    }

    @Test
    void theBallsAreFastSlowAndTouchingGizmosFlippersAndEachOther() {
        int touchingGizmo = 0;
        int touchingFlipper = 0;
        int touchingBall = 0;
        int touchingWall = 0;
        int stacked = 0;
        int packed = 0;
        int fast = 0;
        int still = 0;
        Set<Integer> counts = new HashSet<>();
        for (FuzzCase c : CASES) {
            List<BallView> balls = c.board().balls().stream().filter(b -> !b.isCaptured()).toList();
            counts.add(c.board().balls().size());
            for (BallView ball : balls) {
                double x = ball.position().x();
                double y = ball.position().y();
                for (Gizmo g : c.board().gizmos()) {
                    boolean touches = Math.abs(Bodies.of(g).signedDistance(x, y) - Board.BALL_RADIUS) < 1e-9;
                    touchingGizmo += touches ? 1 : 0;
                    touchingFlipper += touches && g instanceof Flipper ? 1 : 0;
                }
                int neighbours = 0;
                for (BallView other : balls) {
                    double d = Math.hypot(x - other.position().x(), y - other.position().y());
                    boolean touches = other != ball && Math.abs(d - 2 * Board.BALL_RADIUS) < 1e-9;
                    touchingBall += touches ? 1 : 0;
                    neighbours += touches ? 1 : 0;
                    stacked += touches && Math.abs(x - other.position().x()) < 1e-9 ? 1 : 0;
                }
                packed += neighbours >= 4 ? 1 : 0;
                double wallGap = Math.min(Math.min(x, Board.SIZE - x), Math.min(y, Board.SIZE - y));
                touchingWall += Math.abs(wallGap - Board.BALL_RADIUS) < 1e-9 ? 1 : 0;
                double speed = ball.velocity().length();
                fast += speed > 80 ? 1 : 0;
                still += speed == 0 ? 1 : 0;
            }
        }
        assertThat(touchingGizmo).isGreaterThan(300);
        assertThat(touchingFlipper).isGreaterThan(50);
        assertThat(touchingBall).isGreaterThan(100);
        assertThat(stacked).as("balls on top of balls").isGreaterThan(20);
        assertThat(packed).as("balls touching four others or more (packed pockets)").isGreaterThan(60);
        assertThat(touchingWall).isGreaterThan(50);
        assertThat(fast).isGreaterThan(100);
        assertThat(still).isGreaterThan(100);
        assertThat(counts).contains(5, 40).hasSizeGreaterThan(25);
    }

    @Test
    void theKeyScriptsPressAndReleaseTheBoardsKeysThroughTheRun() {
        int pressed = 0;
        for (FuzzCase c : CASES) {
            Set<Integer> bound = new HashSet<>();
            c.board().keyBindings().forEach(k -> bound.add(k.keyCode()));
            for (KeyScript.Press press : c.keys().presses()) {
                assertThat(bound).contains(press.code());
                assertThat(press.tick()).isBetween(1, TICKS);
            }
            pressed += c.keys().presses().stream().anyMatch(p -> !p.down() && p.tick() > TICKS / 2) ? 1 : 0;
        }
        assertThat(pressed).as("boards with keys still released late in the run").isGreaterThan(50);
    }

    private static boolean touchesAnother(Board board, Flipper flipper) {
        for (Gizmo g : board.gizmos()) {
            boolean apart = g.x() > flipper.x() + 2 || g.x() + g.width() < flipper.x() || g.y() > flipper.y() + 2
                    || g.y() + g.height() < flipper.y();
            if (g != flipper && !apart) {
                return true;
            }
        }
        return false;
    }
}
