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
    SQUARE("Square", GizmoKind.SQUARE, "<name> <x> <y>"),
    CIRCLE("Circle", GizmoKind.CIRCLE, "<name> <x> <y>"),
    TRIANGLE("Triangle", GizmoKind.TRIANGLE, "<name> <x> <y>"),
    LEFT_FLIPPER("LeftFlipper", GizmoKind.LEFT_FLIPPER, "<name> <x> <y>"),
    RIGHT_FLIPPER("RightFlipper", GizmoKind.RIGHT_FLIPPER, "<name> <x> <y>"),
    ABSORBER("Absorber", GizmoKind.ABSORBER, "<name> <x1> <y1> <x2> <y2>"),
    BALL("Ball", null, "<name> <x> <y> <vx> <vy>"),
    ROTATE("Rotate", null, "<name>"),
    DELETE("Delete", null, "<name>"),
    MOVE("Move", null, "<name> <x> <y>"),
    CONNECT("Connect", null, "<name1> <name2>"),
    KEY_CONNECT("KeyConnect", null, "key <keycode> down|up|change <name>"),
    COLOUR("Colour", null, "<name> <red> <green> <blue>"),
    /** Play state: a flipper's angle and direction, written by a save during play. */
    FLIPPER_STATE("FlipperAngle", null, "<name> <degrees> up|down", true),
    GRAVITY("Gravity", null, "<g>"),
    FRICTION("Friction", null, "<mu> <mu2>"),
    /** The game: balls per game. */
    BALLS("Balls", null, "<balls>", true),
    /** The game: the score that gives an extra ball. */
    EXTRA_BALL("ExtraBall", null, "<score>", true),
    /** The game: an absorber whose captured balls are lost. */
    DRAIN("Drain", null, "<name>", true),
    /** The game: what a hit on the gizmo scores. */
    POINTS("Points", null, "<name> <points>", true);

    /** What comes before the word of each of our commands: no space, so that {@code #@ text} stays a comment. */
    static final String OURS = "#@";

    private static final Map<String, CommandWord> BY_LOWER_CASE = Arrays.stream(values())
            .collect(Collectors.toUnmodifiableMap(w -> w.spelling.toLowerCase(Locale.ROOT), Function.identity()));

    private final String spelling;
    private final GizmoKind kind;
    private final String usage;
    private final boolean ours;

    /** A command of the standard format. */
    CommandWord(String spelling, GizmoKind kind, String arguments) {
        this(spelling, kind, arguments, false);
    }

    /**
     * @param kind the gizmo the command adds, or null for the other commands
     * @param ours an addition of this game to the standard format, written {@code #@Word}
     */
    CommandWord(String spelling, GizmoKind kind, String arguments, boolean ours) {
        this.spelling = spelling;
        this.kind = kind;
        this.ours = ours;
        this.usage = (ours ? OURS : "") + spelling + " " + arguments;
    }

    /** The canonical spellings of all the commands (for the nearest one to a misspelling). */
    static List<String> spellings() {
        return Arrays.stream(values()).map(CommandWord::spelling).toList();
    }

    /** The command that adds a gizmo of that kind. */
    static CommandWord of(GizmoKind kind) {
        return Arrays.stream(values()).filter(word -> word.kind == kind).findFirst().orElseThrow();
    }

    /**
     * The command word in any letter case (files from other implementations vary), with or without {@link #OURS}
     * before it (whether it belongs there is the parser's question).
     */
    static Optional<CommandWord> lookup(String word) {
        String bare = word.startsWith(OURS) ? word.substring(OURS.length()) : word;
        return Optional.ofNullable(BY_LOWER_CASE.get(bare.toLowerCase(Locale.ROOT)));
    }

    /** The gizmo this command adds (Square ... RightFlipper, Absorber). */
    GizmoKind kind() {
        if (kind == null) {
            throw new IllegalStateException(spelling + " adds no gizmo");
        }
        return kind;
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

    /** How the command is written, for error messages. */
    String usage() {
        return usage;
    }

    int argumentCount() {
        return usage.split(" ").length - 1;
    }
}
