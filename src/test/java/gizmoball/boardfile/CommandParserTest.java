package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.loop.TriggerSource;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

class CommandParserTest {

    static Stream<Arguments> wellFormedLines() {
        return Stream.of(
                Arguments.of("Square S1 1 2", new Command.AddGizmo(GizmoKind.SQUARE, "S1", 1, 2)),
                Arguments.of("circle C 3 4", new Command.AddGizmo(GizmoKind.CIRCLE, "C", 3, 4)),
                Arguments.of("TRIANGLE T 19 0", new Command.AddGizmo(GizmoKind.TRIANGLE, "T", 19, 0)),
                Arguments.of("LeftFlipper LF 7.0 8.0", new Command.AddGizmo(GizmoKind.LEFT_FLIPPER, "LF", 7, 8)),
                Arguments.of("rightflipper 12_4 10 11", new Command.AddGizmo(GizmoKind.RIGHT_FLIPPER, "12_4", 10, 11)),
                Arguments.of("Absorber A 0 19 20 20", new Command.AddAbsorber("A", 0, 19, 20, 20)),
                Arguments.of("Ball B 1.5 2.25 -3 40.0", new Command.AddBall("B", 1.5, 2.25, -3, 40)),
                Arguments.of("Rotate S1", new Command.Rotate("S1")),
                Arguments.of("delete S1", new Command.Delete("S1")),
                Arguments.of("Move B 3.5 4", new Command.Move("B", 3.5, 4)),
                Arguments.of("Connect A A", new Command.Connect(TriggerSource.gizmo("A"), "A")),
                Arguments.of("Connect OuterWalls LF", new Command.Connect(TriggerSource.OUTER_WALLS, "LF")),
                Arguments.of("KeyConnect key 32 down A", new Command.KeyConnect(32, KeyEdge.DOWN, "A")),
                Arguments.of("keyconnect KEY 76.0 UP L", new Command.KeyConnect(76, KeyEdge.UP, "L")),
                Arguments.of("KeyConnect key 70 change F", new Command.KeyConnect(70, KeyEdge.CHANGE, "F")),
                Arguments.of("Colour RF137 255 255 0", new Command.Colour("RF137", new Rgb(255, 255, 0))),
                Arguments.of("Gravity 25.0", new Command.Gravity(25)),
                Arguments.of("Friction 0.025 0.025", new Command.Friction(0.025, 0.025)),
                Arguments.of("Square !@$%^&*()-=+[]{};:'\",.<>/?|\\~` 0 0",
                        new Command.AddGizmo(GizmoKind.SQUARE, "!@$%^&*()-=+[]{};:'\",.<>/?|\\~`", 0, 0)),
                Arguments.of("\t Square   S \t 1   2  ", new Command.AddGizmo(GizmoKind.SQUARE, "S", 1, 2)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("wellFormedLines")
    void parsesWellFormedLines(String line, Command expected) throws Refusal {
        assertThat(CommandParser.parse(line)).isEqualTo(new CommandParser.Parsed(expected, List.of()));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("wellFormedLines")
    void canonicalLineParsesBackToTheSameCommand(String line, Command command) throws Refusal {
        assertThat(CommandParser.parse(command.toLine()).command()).isEqualTo(command);
    }

    static Stream<Arguments> malformedLines() {
        return Stream.of(
                Arguments.of("Colour S1 #ff00", "colour '#ff00' is neither #rrggbb nor a 32-bit ARGB number"),
                Arguments.of("Colour S1 1.5", "colour '1.5' is neither #rrggbb nor a 32-bit ARGB number"),
                Arguments.of("Colour S1 256 0 0", "red 256 is not a colour channel 0..255"),
                Arguments.of("Color S1 0 0", "wrong number of arguments: Colour takes <name> and"),
                Arguments.of("Multiball S 1 2", "Multiball S: an extension of another implementation, not part of the format"),
                Arguments.of("Sink S 1 2 3", "wrong number of arguments: 'Sink' of another implementation is read as"
                        + " #@Sink, which takes 3 (#@Sink <name> <x> <y>), found 4"),
                Arguments.of("Booster 0_2 0", "wrong number of arguments: 'Booster' of another implementation is read"
                        + " as #@Accelerator, which takes 3 (#@Accelerator <name> <x> <y>), found 2"),
                Arguments.of("Flipper F1 1 2", "a Flipper of no known side"),
                Arguments.of("Bumper", "unknown command 'Bumper'"),
                Arguments.of("Sqaure S1 1 1", "unknown command 'Sqaure' (did you mean Square?)"),
                Arguments.of("Foo bar", "unknown command 'Foo'"),
                Arguments.of("Foo bar 1 2", "unknown command 'Foo'"),
                Arguments.of("Circel C 1 1", "unknown command 'Circel' (did you mean Circle?)"),
                Arguments.of("KeyConect key 32 down A", "unknown command 'KeyConect' (did you mean KeyConnect?)"),
                Arguments.of("Gravty 25", "unknown command 'Gravty' (did you mean Gravity?)"),
                Arguments.of("Rhombus SP 1 1", "Rhombus SP: an extension of another implementation, not part of the format"),
                Arguments.of("MouseConnect 1 A", "MouseConnect: an extension of another implementation, not part of the format"),
                Arguments.of("Square S1 1", "wrong number of arguments: Square takes 3 (Square <name> <x> <y>), found 2"),
                Arguments.of("LeftFlipper LF87 8 7 false", "wrong number of arguments: LeftFlipper takes 3"),
                Arguments.of("Absorber A 0 19", "wrong number of arguments: Absorber takes 5"),
                Arguments.of("Ball B 1.0", "wrong number of arguments: Ball takes 5"),
                Arguments.of("Delete", "wrong number of arguments: Delete takes 1"),
                Arguments.of("Circle C0 jkj 3", "x 'jkj' is not a number"),
                Arguments.of("Ball B 1 2 NaN 0", "vx 'NaN' is not a number"),
                Arguments.of("Gravity Infinity", "gravity 'Infinity' is not a number"),
                Arguments.of("Friction 0.025 1e999", "mu2 '1e999' is not a number"),
                Arguments.of("Square S 1.5 2", "x coordinate 1.5 is not a whole cell"),
                Arguments.of("Absorber A 0 19 20 19.75", "y2 coordinate 19.75 is not a whole cell"),
                Arguments.of("Square S 1e12 2", "x coordinate 1e12 is outside the board"),
                Arguments.of("KeyConnect key 32 sideways A", "bad direction 'sideways': expected down, up or change"),
                Arguments.of("KeyConnect key 15 down A", "unknown key code 15"),
                Arguments.of("KeyConnect key 0 down A", "unknown key code 0"),
                Arguments.of("KeyConnect key Spacebar down A", "unknown key Spacebar: neither a key code nor"),
                Arguments.of("KeyConnect key 32 down A B", "wrong number of arguments: KeyConnect takes 4"),
                Arguments.of("KeyConnect key 76.5 down A", "key code 76.5 is not a whole number"),
                Arguments.of("KeyConnect button 32 down A", "expected the word 'key' after KeyConnect, found 'button'"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("malformedLines")
    void refusesMalformedLinesSayingWhy(String line, String reason) {
        assertThatThrownBy(() -> CommandParser.parse(line)).isInstanceOf(Refusal.class)
                .hasMessageStartingWith(reason);
    }
}
