package gizmoball.stability;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.LoopModes;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.LoopMode;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.MethodSource;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;

import static org.assertj.core.api.Assertions.assertThat;

/**
 * Failure mode (docs/design.md, "Failure modes": fast balls): very fast balls. At the speed limit, 200 L/s, a ball moves 3.3 L per tick at
 * 1/60 s, more than any gizmo is thick: stepping and testing for overlap would tunnel; exact collision
 * times must not, against thin corners and moving flippers included.
 */
class FastBallTest {

    private static final double DT = Board.DEFAULT_TICK;
    private static final double R = Board.BALL_RADIUS;
    private static final long SEED = 20261130L;

    /** Straight at the tip of a triangle and at a square's corner at top speed: it comes back, never through. */
    @ParameterizedTest
    @EnumSource(LoopMode.class)
    void topSpeedAtThinCornersBouncesBack(LoopMode mode) {
        Board board = FreeSpace.board(mode);
        board.addGizmo(GizmoKind.TRIANGLE, "T", 10, 5);   // corners (10,5), (11,5), (10,6): tip (11,5) points right
        board.addGizmo(GizmoKind.SQUARE, "S", 10, 14);
        board.addBall("atTip", 18, 5.1, -Board.MAX_SPEED, 0);
        board.addBall("atCorner", 5, 13.95, Board.MAX_SPEED, 0);
        // 3 ticks = 0.05 s: each ball has hit its corner (after 0.034 s and 0.024 s) and no wall yet.
        new Watch("200 L/s at thin corners", board, DT).run(3, (tick, b) -> {
            BallView atTip = b.balls().get(0);
            BallView atCorner = b.balls().get(1);
            assertThat(atTip.position().x()).as("tip ball stays right of the tip at tick " + tick).isGreaterThan(11);
            assertThat(atCorner.position().x()).as("corner ball stays left of the square at tick " + tick).isLessThan(10);
        });
        assertThat(board.balls().get(0).velocity().x()).as("tip ball bounced").isPositive();
        assertThat(board.balls().get(1).velocity().x()).as("corner ball bounced").isNegative();
    }

    static Stream<Arguments> randomThrows() {
        Random random = new Random(SEED);
        List<Arguments> cases = new ArrayList<>();
        for (int i = 0; i < 12; i++) {
            double angle = random.nextDouble() * 2 * Math.PI;
            long boardSeed = random.nextLong();
            for (LoopMode mode : LoopMode.values()) {
                cases.add(Arguments.of(mode, angle, boardSeed));
            }
        }
        return cases.stream();
    }

    /**
     * A ball thrown at 200 L/s in a random direction among random bumpers and two flippers working on a
     * key, three balls in all; seeds are in the test name.
     */
    @ParameterizedTest(name = "{0}, angle {1}, board seed {2}")
    @MethodSource("randomThrows")
    void topSpeedAmongBumpersAndFlippers(LoopMode mode, double angle, long boardSeed) {
        Board board = new Board();
        LoopModes.set(board, mode);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 6, 16);
        board.addGizmo(GizmoKind.RIGHT_FLIPPER, "RF", 12, 16);
        board.bindKey(32, KeyEdge.DOWN, "LF");
        board.bindKey(32, KeyEdge.UP, "LF");
        board.bindKey(32, KeyEdge.DOWN, "RF");
        board.bindKey(32, KeyEdge.UP, "RF");
        Random random = new Random(boardSeed);
        GizmoKind[] kinds = {GizmoKind.SQUARE, GizmoKind.CIRCLE, GizmoKind.TRIANGLE};
        for (int i = 0; i < 40; i++) {
            int x = random.nextInt(Board.SIZE);
            int y = 2 + random.nextInt(13);
            if (board.placementProblem(GizmoKind.SQUARE, x, y, 1, 1, null).isEmpty()) {
                String name = "G" + i;
                board.addGizmo(kinds[random.nextInt(kinds.length)], name, x, y);
                for (int t = random.nextInt(4); t > 0; t--) {
                    board.rotate(name);
                }
            }
        }
        board.addBall("fast", 10.5, 0.5, Board.MAX_SPEED * Math.cos(angle), Board.MAX_SPEED * Math.sin(angle));
        board.addBall("slow", 3.5, 0.5, 5, 0);
        board.addBall("dropped", 16.5, 0.5, 0, 0);
        new Watch("200 L/s among bumpers, angle " + angle + ", board seed " + boardSeed, board, DT)
                .energyMayGrow().run(600, (tick, b) -> {
                    if (tick % 20 == 0) {
                        b.keyDown(32);
                    } else if (tick % 20 == 10) {
                        b.keyUp(32);
                    }
                });
    }
}
