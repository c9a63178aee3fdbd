package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.DropTargetView;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.GateView;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

/**
 * A board saved at any moment of play loads again strictly, with its balls, flipper angles and absorber contents as
 * they were (docs/design.md, "Tolerances": the loop never leaves a ball deeper than the loader accepts).
 */
class PlayStateRoundTripTest {
    private static final double DT = 1.0 / 60;

    /** What play state a file must keep: every ball exactly, every flipper's angle and direction. */
    private record State(List<String> balls, List<String> flippers) {
        static State of(Board board) {
            List<String> balls = new ArrayList<>();
            for (BallView ball : board.balls()) {
                balls.add(ball.name() + " " + ball.position() + " " + ball.velocity() + " " + ball.isCaptured());
            }
            List<String> flippers = new ArrayList<>();
            for (Gizmo gizmo : board.gizmos()) {
                if (gizmo instanceof FlipperView flipper) {
                    flippers.add(flipper.name() + " " + flipper.angleFromRest() + " " + flipper.isActive());
                }
            }
            return new State(balls, flippers);
        }
    }

    private static Board playedAndReloaded(Board board) throws BoardFileException {
        return BoardFiles.load("played", BoardFiles.toText(board));
    }

    /** Random boards, flippers toggled now and then, played for up to 3,000 ticks and saved at random moments. */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {101, 102, 103, 104, 105, 106, 107, 108})
    void aBoardSavedDuringPlayLoadsAgainAsItWas(long seed) throws BoardFileException {
        Random random = new Random(seed);
        Board board = new RandomBoards(random).next();
        List<String> flippers = board.gizmos().stream()
                .filter(g -> g.kind() == GizmoKind.LEFT_FLIPPER || g.kind() == GizmoKind.RIGHT_FLIPPER)
                .map(Gizmo::name).toList();
        for (int save = 0; save < 5; save++) {
            int ticks = 1 + random.nextInt(600);
            for (int t = 0; t < ticks; t++) {
                if (!flippers.isEmpty() && random.nextInt(40) == 0) {
                    board.trigger(flippers.get(random.nextInt(flippers.size())));
                }
                board.tick(DT);
            }
            Board reloaded = playedAndReloaded(board);
            assertThat(State.of(reloaded)).as("seed %d, save %d", seed, save).isEqualTo(State.of(board));
            assertThat(BoardFiles.toText(reloaded)).isEqualTo(BoardFiles.toText(board));
        }
    }

    @Test
    void theStressBoardAfterSixHundredTicksLoadsAgain() throws Exception {
        Board board = BoardFiles.load(java.nio.file.Path.of("boards", "stress.txt"));
        for (int t = 0; t < 600; t++) {
            board.tick(DT);
        }
        assertThat(State.of(playedAndReloaded(board))).isEqualTo(State.of(board));
    }

    /** A ball lying under a raised flipper: the file says the flipper is up, so the ball fits. */
    @Test
    void aBallUnderARaisedFlipperLoadsBecauseTheFlipperIsWrittenRaised() throws BoardFileException {
        Board board = new Board();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 5, 10);
        board.bindKey(90, KeyEdge.DOWN, "LF");
        board.keyDown(90);
        for (int t = 0; t < 10; t++) {
            board.tick(DT);
        }
        board.addBall("B", 5.25, 11.5, 0, 0);   // where the flipper hung at rest
        String text = BoardFiles.toText(board);
        assertThat(text).contains("#@FlipperAngle LF 90.0 up");
        assertThat(State.of(BoardFiles.load("raised", text))).isEqualTo(State.of(board));
    }

    @Test
    void aBoardAsBuiltIsWrittenWithoutPlayState() {
        Board board = new Board();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 5, 10);
        assertThat(BoardFiles.toText(board)).doesNotContain("#@");
    }

    @Test
    void otherCommentLinesStayComments() throws BoardFileException {
        Board board = BoardFiles.load("comments", "#@ a note of another implementation\n#FlipperAngle X\nGravity 10\n");
        assertThat(board.gravity()).isEqualTo(10);
    }

    /**
     * A gate play has opened with a ball in its cell, and a drop target a ball has knocked down, saved during play,
     * load again open and down: read as built, the closed gate would be around the ball, and the board would not load.
     */
    @Test
    void anOpenGateAndADownTargetLoadAgainOpenAndDown() throws BoardFileException {
        Board board = new Board();
        board.addGizmo(GizmoKind.GATE, "G", 5, 10);
        board.addGizmo(GizmoKind.DROP_TARGET, "D", 12, 19);
        board.trigger("G");   // a gate's default action: it opens
        board.setGravity(0);
        board.addBall("InGate", 5.5, 10.5, 0, 0);
        board.addBall("Falling", 12.5, 17.5, 0, 5);
        for (int t = 0; t < 60; t++) {
            board.tick(DT);
        }
        String saved = BoardFiles.toText(board);
        assertThat(saved).contains("#@Open G", "#@Open D");

        Board reloaded = BoardFiles.load("played", saved);

        assertThat(((GateView) reloaded.gizmo("G").orElseThrow()).isOpen()).isTrue();
        assertThat(((DropTargetView) reloaded.gizmo("D").orElseThrow()).isDown()).isTrue();
        assertThat(State.of(reloaded)).isEqualTo(State.of(board));
    }
}
