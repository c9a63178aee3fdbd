package gizmoball.preview;

import gizmoball.model.gizmo.Setting;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.boardfile.BoardFiles;
import gizmoball.controller.GameLoop;
import gizmoball.editor.Preview;
import gizmoball.editor.Tool;
import gizmoball.model.Board;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.TriggerSource;
import gizmoball.session.GameSession;
import gizmoball.session.Mode;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.api.Test;
import physics.Vect;

/** The aim preview's prediction against what the game then plays. */
class PredictorTest {
    private static final double DT = Board.DEFAULT_TICK;
    private static final int TICKS = 180;
    /** A predictor whose budget never runs out: the clock stands still. */
    private final Predictor unhurried = new Predictor(() -> 0L);

    static Stream<String> sampleBoardBalls() throws Exception {
        return Stream.of("default.txt", "multiball.txt", "rube-goldberg.txt", "stress.txt").flatMap(file -> {
            try {
                return BoardFiles.load(Path.of("boards", file)).balls().stream().map(b -> file + " " + b.name());
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        });
    }

    @ParameterizedTest
    @MethodSource("sampleBoardBalls")
    void thePredictedPathIsThePathTheBallTakesInPlay(String boardAndBall) throws Exception {
        String[] parts = boardAndBall.split(" ");
        GameSession session = new GameSession();
        session.setMode(Mode.BUILD);
        session.load(BoardFiles.load(Path.of("boards", parts[0])), Path.of("boards", parts[0]));
        assertPredictedAsPlayed(session, parts[1]);
    }

    /** A ball dropped onto a spinner, batted on among spinners turning either way, is predicted as it plays. */
    @Test
    void aBallBattedBySpinnersIsPredictedAsItPlays() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SPINNER, "SN1", 8, 10);
        board.addGizmo(GizmoKind.SPINNER, "SN2", 12, 12);
        board.set("SN2", new Setting.Speed(-2.5));
        board.addBall("B", 9.6, 6, 0, 0);
        GameSession session = new GameSession();
        session.setMode(Mode.BUILD);
        session.loadSample(board, "spinners");
        assertPredictedAsPlayed(session, "B");
        assertThat(session.board().gizmo("SN1").orElseThrow().lastTriggeredAt()).as("the spinner bats it").isFinite();
    }

    /** The prediction of the ball on the session's board in build mode is, tick by tick, what play then does. */
    private void assertPredictedAsPlayed(GameSession session, String ball) {
        Prediction p = unhurried.predict(session.board(), ball, Predictor.HORIZON_SECONDS, DT, Predictor.BUDGET_NANOS);
        assertThat(p.ticks()).isEqualTo(TICKS);
        assertThat(p.shortened()).isFalse();
        assertThat(p.seconds()).isCloseTo(3, within(1e-9));

        // Play, as the window does: switch to play mode and let the loop step, no key pressed.
        session.setMode(Mode.PLAY);
        GameLoop loop = new GameLoop(session.board(), DT);
        assertThat(position(session.board(), ball)).isEqualTo(p.path().get(0).at());
        for (int i = 1; i <= TICKS; i++) {
            loop.step();
            Vect played = position(session.board(), ball);
            Vect predicted = p.path().get(i).at();
            assertThat(played.minus(predicted).length()).as("tick %d", i).isLessThanOrEqualTo(1e-9);
            if (session.board().ball(ball).orElseThrow().isCaptured()) {
                assertThat(p.path().get(i).free()).as("held at tick %d", i).isFalse();
            }
        }
    }

    @Test
    void predictingLeavesTheBoardAsItWas() throws Exception {
        Board board = BoardFiles.load(Path.of("boards", "multiball.txt"));
        String before = BoardFiles.toText(board);
        unhurried.predict(board, "B1", 3, DT, Long.MAX_VALUE);
        assertThat(BoardFiles.toText(board)).isEqualTo(before);
        assertThat(board.time()).isZero();
    }

    /** A ball dropped from (10.5, 2) falls freely down x = 10.5; a square in cell (10, 10) stops it at y = 9.75. */
    @Test
    void aGizmoPlacedAcrossThePathChangesIt() {
        Board board = new Board();
        board.setFriction(0, 0);
        board.addBall("B", 10.5, 2, 0, 0);
        Prediction free = unhurried.predict(board, "B", 3, DT, Long.MAX_VALUE);
        double lowest = free.path().stream().mapToDouble(pt -> pt.at().y()).max().orElseThrow();
        assertThat(lowest).as("falls to the floor").isCloseTo(19.75, within(1e-6));

        // While the square is being placed (the editor's footprint under the pointer), and once it is placed.
        Optional<AimScenario> placing = AimScenario.of(board, Tool.SQUARE,
                Optional.of(new Preview.Footprint(10, 10, 1, 1, Optional.empty())), Optional.of("B"), Optional.empty());
        Prediction whilePlacing = unhurried.predict(placing.orElseThrow().board(), "B", 3, DT, Long.MAX_VALUE);
        board.addGizmo(GizmoKind.SQUARE, "S", 10, 10);
        Prediction placed = unhurried.predict(board, "B", 3, DT, Long.MAX_VALUE);

        for (Prediction p : List.of(whilePlacing, placed)) {
            assertThat(p.path().stream().mapToDouble(pt -> pt.at().y()).max().orElseThrow())
                    .as("never below the square's top less a radius").isLessThanOrEqualTo(9.75 + 1e-9);
            assertThat(p.path()).isNotEqualTo(free.path());
        }
        assertThat(whilePlacing.path()).isEqualTo(placed.path());
    }

    @Test
    void aBallASinkTakesEndsItsPathWhereItWentIn() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SINK, "SK", 10, 12);
        board.addGizmo(GizmoKind.CIRCLE, "C", 3, 3);
        board.connect(TriggerSource.gizmo("SK"), "C");
        board.addBall("B", 10.5, 8, 0, 0);
        Prediction p = unhurried.predict(board, "B", 3, DT, Long.MAX_VALUE);
        assertThat(p.shortened()).as("the whole prediction: there is nothing after the sink").isFalse();
        assertThat(p.collisions()).hasSize(1);
        assertThat(p.collisions().get(0).y()).isCloseTo(12 - Board.BALL_RADIUS, within(1e-9));
        assertThat(p.path().get(p.path().size() - 1)).isEqualTo(new Prediction.Point(p.collisions().get(0), false));
        assertThat(p.trigger().orElseThrow().targets()).containsExactly("C");
        assertThat(board.ball("B")).as("the design keeps its ball").isPresent();
    }

    @Test
    void eachCollisionIsADotAndTheFirstTriggerNamesWhatItDrives() {
        Board board = new Board();
        board.setFriction(0, 0);
        board.addGizmo(GizmoKind.SQUARE, "Plain", 10, 6);
        board.addGizmo(GizmoKind.TRIANGLE, "Ramp", 10, 12);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 2, 16);
        board.addGizmo(GizmoKind.CIRCLE, "C", 15, 15);
        board.connect(TriggerSource.gizmo("Ramp"), "LF");
        board.connect(TriggerSource.gizmo("Ramp"), "C");
        board.addBall("B", 10.5, 7.5, 0, 0);   // just below the plain square, falling onto the ramp
        Prediction p = unhurried.predict(board, "B", 3, DT, Long.MAX_VALUE);
        assertThat(p.collisions()).isNotEmpty();
        // The ramp (a triangle, unrotated: its slope faces down-right, its top edge flat) is hit first, on top.
        Vect first = p.collisions().get(0);
        assertThat(first.x()).isCloseTo(10.5, within(1e-9));
        assertThat(first.y()).isCloseTo(12 - Board.BALL_RADIUS, within(1e-9));
        Prediction.Trigger trigger = p.trigger().orElseThrow();
        assertThat(trigger.source()).isEqualTo("Ramp");
        assertThat(trigger.targets()).containsExactly("LF", "C");
        assertThat(trigger.at()).isEqualTo(first);
        // Every dot lies on the path: within one tick's travel of a predicted position.
        for (Vect dot : p.collisions()) {
            assertThat(p.path()).anyMatch(pt -> pt.at().minus(dot).length() <= 40 * DT);
        }
    }

    @Test
    void thePathBreaksWhereAnAbsorberCapturesTheBallEvenIfItFiresItAtOnce() {
        Board board = new Board();
        board.addAbsorber("A", 0, 19, 20, 20);
        board.connect(TriggerSource.gizmo("A"), "A");
        board.addBall("B", 5.5, 17, 0, 0);
        Prediction p = unhurried.predict(board, "B", 1, DT, Long.MAX_VALUE);
        int broken = (int) p.path().stream().filter(pt -> !pt.free()).count();
        assertThat(broken).isEqualTo(1);
        Prediction.Point after = p.path().stream().filter(pt -> !pt.free()).findFirst().orElseThrow();
        // Fired at once from the absorber's launch spot, the bottom-right corner, not from where it landed.
        assertThat(after.at().x()).isCloseTo(19.75, within(1e-9));
        assertThat(p.trigger().orElseThrow().targets()).containsExactly("A");
    }

    @Test
    void aBallBeingPlacedIsPredictedWithTheVelocityDraggedOut() {
        Board board = new Board();
        board.setGravity(0);
        board.setFriction(0, 0);
        AimScenario s = AimScenario.of(board, Tool.BALL,
                Optional.of(new Preview.BallPlacement(5, 5, 10, 0, Optional.empty())), Optional.empty(),
                Optional.empty()).orElseThrow();
        Prediction p = unhurried.predict(s.board(), s.ball(), 1, DT, Long.MAX_VALUE);
        // 10 L/s to the right without forces: 10/60 L per tick until the right wall at 19.75 (after 1.475 s).
        assertThat(p.path().get(30).at().x()).isCloseTo(5 + 30 * 10 * DT, within(1e-9));
        assertThat(board.balls()).as("the design gets no ball").isEmpty();
    }

    @Test
    void withoutABallThereIsNothingToPredict() {
        Board board = new Board();
        board.addGizmo(GizmoKind.CIRCLE, "C", 3, 3);
        assertThat(AimScenario.of(board, Tool.SELECT, Optional.empty(), Optional.of("C"), Optional.empty())).isEmpty();
        assertThat(AimScenario.of(board, Tool.SELECT, Optional.empty(), Optional.empty(), Optional.empty())).isEmpty();
    }

    @Test
    void whenTheBudgetRunsOutTheHorizonIsShortened() {
        long[] now = {0};
        // Every reading of the clock is 1 ms later: each tick appears to cost 1 ms.
        Predictor slow = new Predictor(() -> now[0] += 1_000_000);
        Board board = new Board();
        board.addBall("B", 10.5, 2, 0, 0);
        Prediction p = slow.predict(board, "B", 3, DT, Predictor.BUDGET_NANOS);
        assertThat(p.shortened()).isTrue();
        assertThat(p.ticks()).isBetween(1, 8);
        assertThat(p.seconds()).isEqualTo(p.ticks() * DT);
        Vect fallen = p.path().get(p.ticks()).at();
        assertThat(fallen.y()).isGreaterThan(2);
    }

    @Test
    void aPredictionMadeInSlicesIsTheWholePrediction() throws Exception {
        long[] now = {0};
        Predictor slow = new Predictor(() -> now[0] += 1_000_000);
        Board board = BoardFiles.load(Path.of("boards", "multiball.txt"));
        Predictor.Run run = slow.start(board, "B3", 3, DT);
        int slices = 0;
        Prediction p;
        do {
            p = run.advance(Predictor.BUDGET_NANOS);
            slices++;
        } while (!run.isDone());
        assertThat(slices).isGreaterThan(20);
        assertThat(p.shortened()).isFalse();
        assertThat(p.path()).isEqualTo(unhurried.predict(board, "B3", 3, DT, Long.MAX_VALUE).path());
    }

    private static Vect position(Board board, String ball) {
        return board.ball(ball).map(BallView::position).orElseThrow();
    }
}
