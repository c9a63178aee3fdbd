package gizmoball.boardfile;

import java.util.Arrays;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import java.util.stream.Collectors;

/** The first word of each board-file command: its canonical spelling and the arguments it takes. */
enum CommandWord {
    SQUARE("Square", "<name> <x> <y>"),
    CIRCLE("Circle", "<name> <x> <y>"),
    TRIANGLE("Triangle", "<name> <x> <y>"),
    LEFT_FLIPPER("LeftFlipper", "<name> <x> <y>"),
    RIGHT_FLIPPER("RightFlipper", "<name> <x> <y>"),
    ABSORBER("Absorber", "<name> <x1> <y1> <x2> <y2>"),
    BALL("Ball", "<name> <x> <y> <vx> <vy>"),
    ROTATE("Rotate", "<name>"),
    DELETE("Delete", "<name>"),
    MOVE("Move", "<name> <x> <y>"),
    CONNECT("Connect", "<name1> <name2>"),
    KEY_CONNECT("KeyConnect", "key <keycode> down|up <name>"),
    GRAVITY("Gravity", "<g>"),
    FRICTION("Friction", "<mu> <mu2>");

    private static final Map<String, CommandWord> BY_LOWER_CASE = Arrays.stream(values())
            .collect(Collectors.toUnmodifiableMap(w -> w.spelling.toLowerCase(Locale.ROOT), Function.identity()));

    private final String spelling;
    private final String usage;

    CommandWord(String spelling, String arguments) {
        this.spelling = spelling;
        this.usage = spelling + " " + arguments;
    }

    /** The command word in any letter case (files from other implementations vary). */
    static Optional<CommandWord> lookup(String word) {
        return Optional.ofNullable(BY_LOWER_CASE.get(word.toLowerCase(Locale.ROOT)));
    }

    String spelling() {
        return spelling;
    }

    /** How the command is written, for error messages. */
    String usage() {
        return usage;
    }

    int argumentCount() {
        return usage.split(" ").length - 1;
    }
}
