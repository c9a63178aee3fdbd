package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.model.gizmo.SpinnerView;
import gizmoball.model.loop.BallView;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The wiring kit (docs/design.md, "The wiring kit"): every action of every kind, ordered by a key, does what it says
 * and nothing else; an action a kind lacks is refused; a delay is counted in ticks of the board's clock.
 */
class WiringKitTest {
    private static final double DT = Board.DEFAULT_TICK;
    private static final int KEY = 65;

    /** A board holding one gizmo "G" of the kind (an absorber holding one ball). */
    private static Board boardWith(GizmoKind kind) {
        Board board = new Board();
        if (kind == GizmoKind.ABSORBER) {
            board.addAbsorber("G", 0, 18, 20, 20);
            board.addBall("B", 5, 19, 0, 0);
        } else {
            board.addGizmo(kind, "G", 5, 5);
        }
        return board;
    }

    static Stream<Arguments> everyActionOfEveryKind() {
        List<Arguments> cases = new ArrayList<>();
        for (GizmoKind kind : GizmoKind.values()) {
            for (Action action : kind.actions()) {
                cases.add(Arguments.of(kind, action));
            }
        }
        return cases.stream();
    }

    @ParameterizedTest(name = "{0} {1}")
    @MethodSource("everyActionOfEveryKind")
    void aKeyOrderingAnActionMakesTheGizmoDoJustThat(GizmoKind kind, Action action) {
        Board board = boardWith(kind);
        board.tick(DT);
        board.bindKey(KEY, KeyEdge.DOWN, "G", Order.of(action));
        State before = State.of(board);
        board.keyDown(KEY);

        State after = State.of(board);
        assertThat(board.gizmo("G").orElseThrow().lastTriggeredAt()).as("it flashes").isEqualTo(board.time());
        State expected = expected(kind, action, before);
        assertThat(after).isEqualTo(expected);
    }

    @ParameterizedTest(name = "{0} {1}")
    @MethodSource("everyActionOfEveryKind")
    void aHitOnAConnectedSourceMakesTheGizmoDoWhatTheConnectionSays(GizmoKind kind, Action action) {
        Board board = boardWith(kind);
        board.addGizmo(GizmoKind.SQUARE, "S", 10, 10);
        board.addBall("Drop", 10.5, 8, 0, 0);
        board.connect(gizmoball.model.loop.TriggerSource.gizmo("S"), "G", Order.of(action));
        State before = State.of(board);
        for (int i = 0; i < 120 && !Double.isFinite(board.gizmo("S").orElseThrow().lastTriggeredAt()); i++) {
            board.tick(DT);
        }
        double hit = board.gizmo("S").orElseThrow().lastTriggeredAt();
        assertThat(hit).as("the ball hit the square").isFinite();
        assertThat(board.gizmo("G").orElseThrow().lastTriggeredAt()).as("it flashed at the hit").isEqualTo(hit);
        State expected = expected(kind, action, before);
        assertThat(State.of(board)).isEqualTo(expected);
    }

    @Test
    void aConnectionsDelayCountsFromTheHitToTheNextTickBoundaryItReaches() {
        Board board = boardWith(GizmoKind.RIGHT_FLIPPER);
        board.addGizmo(GizmoKind.SQUARE, "S", 10, 10);
        board.addBall("Drop", 10.5, 8, 0, 0);
        board.connect(gizmoball.model.loop.TriggerSource.gizmo("S"), "G", Order.of(Action.RAISE).after(0.2));
        int ticks = 0;
        while (!Double.isFinite(board.gizmo("S").orElseThrow().lastTriggeredAt())) {
            board.tick(DT);
            ticks++;
        }
        double hit = board.gizmo("S").orElseThrow().lastTriggeredAt();
        // The first boundary at or after hit + 0.2 s: the tick that starts there begins with the flipper rising.
        long boundary = (long) Math.ceil((hit + 0.2) / DT - 1e-6);
        while (ticks < boundary) {
            assertThat(flipper(board).isActive()).as("still down after tick " + ticks).isFalse();
            board.tick(DT);
            ticks++;
        }
        assertThat(flipper(board).isActive()).isFalse();
        board.tick(DT);
        assertThat(flipper(board).isActive()).as("raised at the start of tick " + (boundary + 1)).isTrue();
        assertThat(board.gizmo("G").orElseThrow().lastTriggeredAt()).isEqualTo(boundary * DT,
                org.assertj.core.api.Assertions.within(1e-9));
    }

    @Test
    void aFlipperToggledOrLoweredWhenUpGoesDown() {
        for (Action action : List.of(Action.TOGGLE, Action.LOWER)) {
            Board board = boardWith(GizmoKind.LEFT_FLIPPER);
            board.bindKey(KEY, KeyEdge.DOWN, "G", Order.of(Action.RAISE));
            board.bindKey(KEY + 1, KeyEdge.DOWN, "G", Order.of(action));
            board.keyDown(KEY);
            board.keyDown(KEY + 1);
            assertThat(flipper(board).isActive()).as(action.word()).isFalse();
        }
    }

    @Test
    void aKeyBindingWithoutAnActionDoesWhatItsEdgeDoes() {
        Board board = boardWith(GizmoKind.RIGHT_FLIPPER);
        board.bindKey(KEY, KeyEdge.DOWN, "G");
        board.bindKey(KEY, KeyEdge.UP, "G");
        board.bindKey(KEY + 1, KeyEdge.CHANGE, "G");
        board.keyDown(KEY);
        assertThat(flipper(board).isActive()).as("raised on the press").isTrue();
        board.keyUp(KEY);
        assertThat(flipper(board).isActive()).as("lowered on the release").isFalse();
        board.keyDown(KEY + 1);
        assertThat(flipper(board).isActive()).as("toggled by a change").isTrue();
    }

    @Test
    void anActionThatIsTheEdgesOwnIsKeptAsNoActionSoOneMeaningHasOneForm() {
        Board board = boardWith(GizmoKind.LEFT_FLIPPER);
        board.bindKey(KEY, KeyEdge.DOWN, "G", Order.of(Action.RAISE));
        board.bindKey(KEY, KeyEdge.UP, "G", Order.of(Action.RAISE));
        assertThat(board.keyBindings()).containsExactly(new KeyBinding(KEY, KeyEdge.DOWN, "G"),
                new KeyBinding(KEY, KeyEdge.UP, "G", Order.of(Action.RAISE)));
    }

    @ParameterizedTest
    @EnumSource(GizmoKind.class)
    void anActionTheKindLacksIsRefusedNamingWhatItCanDo(GizmoKind kind) {
        Board board = boardWith(kind);
        for (Action action : Action.values()) {
            if (!kind.actions().contains(action)) {
                assertThatThrownBy(() -> board.bindKey(KEY, KeyEdge.DOWN, "G", Order.of(action)))
                        .isInstanceOf(BoardEditException.class)
                        .hasMessageContaining("G is " + kind.withArticle() + ", which can ")
                        .hasMessageEndingWith("not " + action.word());
            }
        }
        assertThat(board.keyBindings()).isEmpty();
    }

    @Test
    void aDelayOutsideZeroToAnHourIsRefused() {
        Board board = boardWith(GizmoKind.SQUARE);
        for (double delay : new double[] {-0.1, Order.MAX_DELAY + 1, Double.NaN, Double.POSITIVE_INFINITY}) {
            assertThatThrownBy(() -> board.bindKey(KEY, KeyEdge.DOWN, "G", Order.DEFAULT.after(delay)))
                    .isInstanceOf(BoardEditException.class).hasMessageStartingWith("a delay is 0 to 3600 seconds");
        }
    }

    @Test
    void aDelayedActionHappensAtTheFirstTickBoundaryItsDelayReaches() {
        Board board = boardWith(GizmoKind.ABSORBER);
        board.bindKey(KEY, KeyEdge.DOWN, "G", Order.DEFAULT.after(0.5));   // 30 ticks of 1/60 s
        board.keyDown(KEY);
        BallView ball = board.ball("B").orElseThrow();
        for (int tick = 1; tick <= 30; tick++) {
            board.tick(DT);
            assertThat(ball.isCaptured()).as("held after tick " + tick).isTrue();
        }
        assertThat(board.gizmo("G").orElseThrow().lastTriggeredAt()).as("no flash before the action").isLessThan(0.01);
        board.tick(DT);
        assertThat(ball.isCaptured()).as("fired before tick 31 ran").isFalse();
        assertThat(board.gizmo("G").orElseThrow().lastTriggeredAt()).isEqualTo(30 * DT, org.assertj.core.api.Assertions.within(1e-12));
    }

    @Test
    void aDelayShorterThanATickWaitsForTheNextBoundaryAndTwoDueTogetherKeepTheirOrder() {
        Board board = boardWith(GizmoKind.LEFT_FLIPPER);
        board.bindKey(KEY, KeyEdge.DOWN, "G", Order.of(Action.RAISE).after(0.001));
        board.bindKey(KEY + 1, KeyEdge.DOWN, "G", Order.of(Action.LOWER).after(0.001));
        board.keyDown(KEY);
        board.keyDown(KEY + 1);
        assertThat(flipper(board).isActive()).isFalse();
        board.tick(DT);
        assertThat(flipper(board).isActive()).as("raised, then lowered, both before the second tick").isFalse();
        assertThat(flipper(board).isMoving()).as("nothing moved it yet").isFalse();
        board.keyDown(KEY);
        board.tick(DT);
        board.tick(DT);
        assertThat(flipper(board).isActive()).as("raised alone").isTrue();
    }

    @Test
    void aCopyOfTheBoardKeepsTheDelayedActionsAndADeletedGizmoDropsItsOwn() {
        Board board = boardWith(GizmoKind.ABSORBER);
        board.bindKey(KEY, KeyEdge.DOWN, "G", Order.DEFAULT.after(0.1));
        board.keyDown(KEY);
        Board copy = board.copy();
        for (int i = 0; i < 8; i++) {
            copy.tick(DT);
        }
        assertThat(copy.ball("B").orElseThrow().isCaptured()).as("the copy fired too").isFalse();
        board.delete("G");
        for (int i = 0; i < 8; i++) {
            board.tick(DT);
        }
        assertThat(board.gizmos()).isEmpty();
    }

    /** What the action does to a gizmo of the kind at rest (a flipper down, a gate closed). */
    private static State expected(GizmoKind kind, Action action, State before) {
        return switch (action) {
            case RAISE -> kind == GizmoKind.DROP_TARGET ? before : before.withFlipperActive(true);   // a target is up
            case TOGGLE -> kind == GizmoKind.GATE ? before.withGateOpen() : before.withFlipperActive(true);
            case OPEN -> before.withGateOpen();
            case LOWER, CLOSE, FLASH -> before;
            case FIRE -> before.withHeld(0);
            case SPAWN -> before.withOneMoreBall();
            case REVERSE -> before.withSpinnerTurns(-before.spinnerTurns());
            case START -> before;   // a spinner turns from the start
            case STOP -> before.withSpinnerRunning(false);
        };
    }

    private static FlipperView flipper(Board board) {
        return (FlipperView) board.gizmo("G").orElseThrow();
    }

    /**
     * What an action can change: whether the flipper is up, how many balls the absorber holds, how many there are,
     * whether the gate is open, the spinner's speed and way (0 for another kind) and whether it runs.
     */
    private record State(boolean flipperActive, int held, int balls, boolean gateOpen, double spinnerTurns,
                         boolean spinnerRunning) {
        static State of(Board board) {
            Gizmo g = board.gizmo("G").orElseThrow();
            return new State(g instanceof FlipperView f && f.isActive(),
                    (int) board.balls().stream().filter(BallView::isCaptured).count(), board.balls().size(),
                    g instanceof gizmoball.model.gizmo.GateView gate && gate.isOpen(),
                    g instanceof SpinnerView s ? s.turnsPerSecond() : 0, g instanceof SpinnerView s && s.isRunning());
        }

        State withFlipperActive(boolean active) {
            return new State(active, held, balls, gateOpen, spinnerTurns, spinnerRunning);
        }

        State withHeld(int n) {
            return new State(flipperActive, n, balls, gateOpen, spinnerTurns, spinnerRunning);
        }

        State withOneMoreBall() {
            return new State(flipperActive, held, balls + 1, gateOpen, spinnerTurns, spinnerRunning);
        }

        State withGateOpen() {
            return new State(flipperActive, held, balls, true, spinnerTurns, spinnerRunning);
        }

        State withSpinnerTurns(double turns) {
            return new State(flipperActive, held, balls, gateOpen, turns, spinnerRunning);
        }

        State withSpinnerRunning(boolean running) {
            return new State(flipperActive, held, balls, gateOpen, spinnerTurns, running);
        }
    }
}
