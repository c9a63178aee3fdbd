package gizmoball.boardfile;

import gizmoball.model.gizmo.GizmoKind;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import java.util.stream.Collectors;

/**
 * The first word of each board-file command: its canonical spelling and the arguments it takes. The commands of the
 * standard format are written bare; our additions to it ({@link #ours()}) always with {@link #OURS} before the word
 * (docs/board-files.md: a loader that knows only the standard format skips them as comments).
 */
enum CommandWord {
    SQUARE("Square", "<name> <x> <y>"),
    CIRCLE("Circle", "<name> <x> <y>"),
    TRIANGLE("Triangle", "<name> <x> <y>"),
    LEFT_FLIPPER("LeftFlipper", "<name> <x> <y>"),
    RIGHT_FLIPPER("RightFlipper", "<name> <x> <y>"),
    ABSORBER("Absorber", "<name> <x1> <y1> <x2> <y2>"),
    /** Extension gizmo: takes the balls that touch it out of play. */
    SINK("Sink", "<name> <x> <y>", true),
    /** Extension gizmo: a round bumper that speeds the ball up. */
    ACCELERATOR("Accelerator", "<name> <x> <y>", true),
    /** Extension gizmo: adds a ball at its mouth when triggered. */
    SPAWNER("Spawner", "<name> <x> <y>", true),
    /** Extension gizmo: solid or open, switched by triggers. */
    GATE("Gate", "<name> <x> <y>", true),
    /** Extension gizmo: solid until hit, then down until a trigger raises it. */
    DROP_TARGET("DropTarget", "<name> <x> <y>", true),
    /** Extension gizmo: a ball entering its mouth leaves by its pair's. */
    PORTAL("Portal", "<name> <x> <y>", true),
    /** Two portals paired with each other. */
    PAIR("Pair", "<portal> <portal>", true),
    /** Extension gizmo: a bar turning without end about the centre of its 2x2 box. */
    SPINNER("Spinner", "<name> <x> <y>", true),
    /** A spinner's speed and way in turns per second (negative: anticlockwise), where it is not the default. */
    SPINNER_SPEED("SpinnerSpeed", "<name> <turns-per-second>", true),
    /** A spawner's velocity for its balls, where it is not zero. */
    SPAWN_VELOCITY("SpawnVelocity", "<name> <vx> <vy>", true),
    BALL("Ball", "<name> <x> <y> <vx> <vy>"),
    ROTATE("Rotate", "<name>"),
    DELETE("Delete", "<name>"),
    MOVE("Move", "<name> <x> <y>"),
    CONNECT("Connect", "<name1> <name2>"),
    KEY_CONNECT("KeyConnect", "key <keycode> down|up|change <name>"),
    COLOUR("Colour", "<name> <red> <green> <blue>"),
    /** An accelerator's factor, where it is not the default. */
    FACTOR("Factor", "<name> <factor>", true),
    /** An absorber that is a plunger: its full-pull speed and pull time (both optional when read). */
    PLUNGER("Plunger", "<absorber> <full-speed> <pull-seconds>", true),
    /** Play state: a flipper's angle and direction, written by a save during play. */
    FLIPPER_STATE("FlipperAngle", "<name> <degrees> up|down", true),
    /** Play state: a gate play has opened or a drop target it has knocked down (its cell is nothing), written by a save during play. */
    CELL_OPEN("Open", "<name>", true),
    /** Play state: a spinner's angle and whether it turns, written by a save during play. */
    SPINNER_STATE("SpinnerAngle", "<name> <radians> running|stopped", true),
    GRAVITY("Gravity", "<g>"),
    FRICTION("Friction", "<mu> <mu2>"),
    /** The game: balls per game. */
    BALLS("Balls", "<balls>", true),
    /** The game: the score that gives an extra ball. */
    EXTRA_BALL("ExtraBall", "<score>", true),
    /** The game: an absorber whose captured balls are lost. */
    DRAIN("Drain", "<name>", true),
    /** The game: what a hit on the gizmo scores. */
    POINTS("Points", "<name> <points>", true),
    /** The game: the board can be nudged (its speed and keys optional when read). */
    NUDGE("Nudge", "<speed> <left-key> <right-key> <up-key>", true),
    /** The game: how many nudges within how many seconds tilt it. */
    TILT("Tilt", "<nudges> <seconds>", true),
    /** The game: the seconds after a launch in which a drained ball is given back. */
    BALL_SAVE("BallSave", "<seconds>", true);

    /** What comes before the word of each of our commands: no space, so that {@code #@ text} stays a comment. */
    static final String OURS = "#@";

    private static final Map<String, CommandWord> BY_LOWER_CASE = Arrays.stream(values())
            .collect(Collectors.toUnmodifiableMap(w -> w.spelling.toLowerCase(Locale.ROOT), Function.identity()));

    private final String spelling;
    private final String usage;
    private final boolean ours;

    /** A command of the standard format. */
    CommandWord(String spelling, String arguments) {
        this(spelling, arguments, false);
    }

    /**
     * @param ours an addition of this game to the standard format, written {@code #@Word}
     */
    CommandWord(String spelling, String arguments, boolean ours) {
        this.spelling = spelling;
        this.ours = ours;
        this.usage = (ours ? OURS : "") + spelling + " " + arguments;
    }

    /** The canonical spellings of all the commands (for the nearest one to a misspelling). */
    static List<String> spellings() {
        return Arrays.stream(values()).map(CommandWord::spelling).toList();
    }

    /**
     * The command that adds a gizmo of that kind: a switch over every kind without a default, so that a new kind does
     * not compile without its word.
     */
    static CommandWord of(GizmoKind kind) {
        return switch (kind) {
            case SQUARE -> SQUARE;
            case CIRCLE -> CIRCLE;
            case TRIANGLE -> TRIANGLE;
            case LEFT_FLIPPER -> LEFT_FLIPPER;
            case RIGHT_FLIPPER -> RIGHT_FLIPPER;
            case ABSORBER -> ABSORBER;
            case SINK -> SINK;
            case ACCELERATOR -> ACCELERATOR;
            case SPAWNER -> SPAWNER;
            case GATE -> GATE;
            case DROP_TARGET -> DROP_TARGET;
            case PORTAL -> PORTAL;
            case SPINNER -> SPINNER;
        };
    }

    /**
     * The command word in any letter case (files from other implementations vary), with or without {@link #OURS}
     * before it (whether it belongs there is the parser's question).
     */
    static Optional<CommandWord> lookup(String word) {
        String bare = word.startsWith(OURS) ? word.substring(OURS.length()) : word;
        return Optional.ofNullable(BY_LOWER_CASE.get(bare.toLowerCase(Locale.ROOT)));
    }

    /** The gizmo this command adds (Square ... RightFlipper, Absorber), as {@link #of} says. */
    GizmoKind kind() {
        return Arrays.stream(GizmoKind.values()).filter(kind -> of(kind) == this).findFirst()
                .orElseThrow(() -> new IllegalStateException(spelling + " adds no gizmo"));
    }

    /**
     * Whether the command adds a gizmo of a kind {@link GizmoKind#sizedByCorners} (an absorber): its arguments are a
     * name and two corners.
     */
    boolean addsSizedByCorners() {
        return Arrays.stream(GizmoKind.values()).anyMatch(kind -> kind.sizedByCorners() && of(kind) == this);
    }

    /** The word without {@link #OURS}. */
    String spelling() {
        return spelling;
    }

    /** An addition of this game to the standard format: always written with {@link #OURS} before it. */
    boolean ours() {
        return ours;
    }

    /** The word as the writer writes it: {@code #@Drain}, {@code Square}. */
    String written() {
        return ours ? OURS + spelling : spelling;
    }

    /** The line of this word with its arguments, each after a space: {@code Gravity 25.0}. */
    String line(Object... arguments) {
        StringBuilder line = new StringBuilder(written());
        for (Object argument : arguments) {
            line.append(' ').append(argument);
        }
        return line.toString();
    }

    /** How the command is written, for error messages. */
    String usage() {
        return usage;
    }

    int argumentCount() {
        return usage.split(" ").length - 1;
    }
}
