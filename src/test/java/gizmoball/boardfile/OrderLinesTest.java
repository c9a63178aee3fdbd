package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.Order;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;
import org.junit.jupiter.api.Test;

/**
 * The wiring kit's lines: a key binding with an action or a delay is ours, {@code #@KeyConnect ... fire after 0.5};
 * one without is the standard line, written exactly as before.
 */
class OrderLinesTest {
    private static final String BOARD = """
            LeftFlipper LF 6 16
            Absorber A 0 19 20 20
            KeyConnect key 90 down LF
            KeyConnect key 90 up LF
            #@KeyConnect key 32 down A after 0.5
            #@KeyConnect key 88 down LF toggle
            #@KeyConnect key 67 up LF flash after 0.125
            Gravity 25.0
            Friction 0.025 0.025
            """;

    @Test
    void ordersAreReadIntoTheBindingsAndWrittenBackAsTheyWere() throws BoardFileException {
        Board board = BoardFiles.load("test", BOARD);
        assertThat(board.keyBindings()).containsExactly(
                new KeyBinding(90, KeyEdge.DOWN, "LF"),
                new KeyBinding(90, KeyEdge.UP, "LF"),
                new KeyBinding(32, KeyEdge.DOWN, "A", Order.DEFAULT.after(0.5)),
                new KeyBinding(88, KeyEdge.DOWN, "LF", Order.of(Action.TOGGLE)),
                new KeyBinding(67, KeyEdge.UP, "LF", Order.of(Action.FLASH).after(0.125)));
        assertThat(BoardFiles.toText(board)).isEqualTo(BOARD);
    }

    @Test
    void aConnectionWithAnOrderIsOursAndOneWithoutIsTheStandardLine() throws BoardFileException {
        String text = """
                Circle C 2 2
                LeftFlipper LF 6 16
                Absorber A 0 19 20 20
                Connect C LF
                #@Connect C A after 1.5
                #@Connect OuterWalls LF raise after 0.25
                Gravity 25.0
                Friction 0.025 0.025
                """;
        Board board = BoardFiles.load("test", text);
        assertThat(board.connections()).containsExactly(
                new Connection(TriggerSource.gizmo("C"), "LF"),
                new Connection(TriggerSource.gizmo("C"), "A", Order.DEFAULT.after(1.5)),
                new Connection(TriggerSource.OUTER_WALLS, "LF", Order.of(Action.RAISE).after(0.25)));
        assertThat(BoardFiles.toText(board)).isEqualTo(text);
        assertThatThrownBy(() -> BoardFiles.load("t", "Circle C 2 2\nConnect C C flash\n"))
                .isInstanceOf(BoardFileException.class).hasMessageContaining("the line is written #@Connect");
        assertThatThrownBy(() -> BoardFiles.load("t", "Circle C 2 2\n#@Connect C C fire\n"))
                .isInstanceOf(BoardFileException.class).hasMessageContaining("C is a circle, which can flash, not fire");
    }

    @Test
    void anActionThatIsTheEdgesOwnIsWrittenAsTheStandardLine() throws BoardFileException {
        Board board = BoardFiles.load("test", "LeftFlipper LF 6 16\n#@KeyConnect key 90 down LF raise\n");
        assertThat(BoardFiles.toText(board)).contains("\nKeyConnect key 90 down LF\n").doesNotContain("#@");
    }

    @Test
    void aLoaderOfTheStandardFormatSkipsTheOrderedBindingsAsComments() {
        String standard = BOARD.lines().filter(line -> !line.startsWith("#@")).reduce("", (a, b) -> a + b + "\n");
        assertThat(standard).contains("KeyConnect key 90 up LF").doesNotContain("after");
    }

    @Test
    void anOrderWrittenBareAnUnknownActionAndAnActionTheGizmoLacksAreErrorsOfTheirLines() {
        assertThatThrownBy(() -> BoardFiles.load("t", "Absorber A 0 19 20 20\nKeyConnect key 32 down A fire\n"))
                .isInstanceOf(BoardFileException.class)
                .hasMessageContaining("t:2:").hasMessageContaining("an action or a delay is an addition of this"
                        + " game to the format: the line is written #@KeyConnect");
        assertThatThrownBy(() -> BoardFiles.load("t", "Absorber A 0 19 20 20\n#@KeyConnect key 32 down A shoot\n"))
                .isInstanceOf(BoardFileException.class)
                .hasMessageContaining("unknown action 'shoot': an action is one of raise, lower, toggle, fire, open, close, spawn, reverse, start, stop, flash");
        assertThatThrownBy(() -> BoardFiles.load("t", "Absorber A 0 19 20 20\n#@KeyConnect key 32 down A raise\n"))
                .isInstanceOf(BoardFileException.class)
                .hasMessageContaining("A is an absorber, which can fire or flash, not raise");
        assertThatThrownBy(() -> BoardFiles.load("t", "Absorber A 0 19 20 20\n#@KeyConnect key 32 down A after\n"))
                .isInstanceOf(BoardFileException.class)
                .hasMessageContaining("after the target come an action, then 'after <seconds>', each only if given");
        assertThatThrownBy(() -> BoardFiles.load("t", "Absorber A 0 19 20 20\n#@KeyConnect key 32 down A after -1\n"))
                .isInstanceOf(BoardFileException.class)
                .hasMessageContaining("a delay is 0 to 3600 seconds");
    }

    @Test
    void aTargetWrittenTwiceIsStillTheDialectNotAnOrder() throws BoardFileException {
        Board board = BoardFiles.load("t", "Absorber fire 0 19 20 20\nKeyConnect key 32 down fire fire\n");
        assertThat(board.keyBindings()).containsExactly(new KeyBinding(32, KeyEdge.DOWN, "fire"));
    }
}
