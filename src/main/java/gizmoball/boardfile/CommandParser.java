package gizmoball.boardfile;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.game.Nudge;
import gizmoball.model.game.Tilt;
import gizmoball.model.gizmo.Order;
import gizmoball.model.gizmo.Plunger;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.loop.TriggerSource;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.OptionalDouble;
import java.util.OptionalInt;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

/**
 * Turns one command line into a {@link Command}, or says precisely why it cannot. Besides the canonical form it
 * reads the spellings other implementations write (two-word and generic flippers, colours, key names, ondown,
 * reversed absorber corners, balls without velocity...), each with a note saying how it was understood.
 */
final class CommandParser {
    /** Far beyond the board, yet safe to turn into an int: larger whole numbers are refused as outside. */
    private static final double COORDINATE_LIMIT = 1_000_000;
    /** A coordinate this far out is no off-by-one: the writer counted pixels, not cells. */
    private static final double PIXEL_COORDINATES_FROM = 2 * Board.SIZE;
    private static final String NOT_THE_FORMAT = ", not part of the format";
    private static final String EXTENSION = "an extension of another implementation" + NOT_THE_FORMAT;
    /** Gizmos of the MIT 6.170 3-D variant: name, x y z and a size. */
    private static final Set<String> MIT_3D_GIZMOS = Set.of("trianglea", "cube", "wall");
    /**
     * The first words that other implementations' files really use for commands of their own (the peer boards'
     * extensions: gizmos, connections of the mouse, settings); any other unknown word is simply unknown.
     */
    private static final Set<String> PEER_EXTENSIONS = Set.of("booster", "rhombus", "octagon", "multiball", "gate",
            "deathsquare",
            "outerwall", "mouseconnect", "timeperupdate");
    /** How a peer's portal or teleporter is read (the pair comes from a Connect or TeleporterConnect line). */
    private static final String PORTAL_MEANING = "a portal whose mouth faces up (turned by Rotate); a ball entering"
            + " it leaves by the portal a Connect or TeleporterConnect line links it to, as in the game that wrote it";

    /**
     * Other implementations' gizmos that are ours as well, written bare with name, x and y, and how each is read
     * (their code's behaviour: lheckemann's and d-g-n's sinks remove the ball; tomcurran's accelerator speeds it up
     * 1.4 times a hit, d-g-n's booster 2 times; the spinners of tomcurran, d-g-n and NiklavsM turn about the centre
     * of a 2x2 box at 2 pi rad/s, 1080 deg/s and pi rad/s, NiklavsM's reversed by a trigger; tomcurran's portals, d-g-n's
     * and bartoszl's teleporters send a ball on to the one they are connected to, bartoszl's turned as we turn it). A
     * bare {@code Connect} between two portals is such a link too: the loader reads it as {@code #@Pair} (ours would be
     * written {@code #@Connect}).
     */
    private static final Map<String, PeerGizmo> PEER_GIZMOS = Map.of(
            "portal", new PeerGizmo(CommandWord.PORTAL, PORTAL_MEANING),
            "teleporter", new PeerGizmo(CommandWord.PORTAL, PORTAL_MEANING),
            "teleporterconnect", new PeerGizmo(CommandWord.PAIR, "a ball entering either teleporter leaves by the"
                    + " other, turned by their rotations, as in the game that wrote it"),
            "sink", new PeerGizmo(CommandWord.SINK, "a ball that touches it leaves the board, as in the game that"
                    + " wrote it"),
            "accelerator", new PeerGizmo(CommandWord.ACCELERATOR, "a round bumper that speeds the ball up "
                    + Decimals.format(Setting.Factor.DEFAULT) + " times a hit (1.4 times in the game that wrote it:"
                    + " #@Factor sets it)"),
            "spawner", new PeerGizmo(CommandWord.SPAWNER, "adds a ball at rest above it when triggered, as the game"
                    + " that wrote it adds one (#@SpawnVelocity gives it a velocity)"),
            "booster", new PeerGizmo(CommandWord.ACCELERATOR, "a round bumper that speeds the ball up "
                    + Decimals.format(Setting.Factor.DEFAULT) + " times a hit (2 times in the game that wrote it:"
                    + " #@Factor sets it)"),
            "spinner", new PeerGizmo(CommandWord.SPINNER, "a bar turning without end about the centre of its 2x2"
                    + " box, " + Decimals.format(Setting.Speed.DEFAULT) + " turn a second clockwise, that a"
                    + " trigger reverses (the games that wrote them turn theirs half a turn to 3 turns a second:"
                    + " #@SpinnerSpeed sets it)"));

    /** A peer's gizmo command read as one of ours: the word it is read as, and what that means here. */
    private record PeerGizmo(CommandWord word, String meaning) {
    }

    private static final Pattern AXES = Pattern.compile("[XYZ]{2}", Pattern.CASE_INSENSITIVE);
    private static final Pattern WORD = Pattern.compile("[A-Za-z][A-Za-z0-9_]*");
    private static final Pattern HEX_COLOUR = Pattern.compile("#[0-9a-fA-F]{6}");

    private CommandParser() {
    }

    /** Thrown for a line that is not a well-formed command; the message is the reason. */
    static final class Refusal extends Exception {
        private static final long serialVersionUID = 1L;

        Refusal(String reason) {
            super(reason);
        }
    }

    /**
     * A command and how its line was understood where it was not written canonically.
     *
     * @param notes empty for a canonical line
     */
    record Parsed(Command command, List<String> notes) {
        Parsed {
            notes = List.copyOf(notes);
        }
    }

    static Parsed parse(String line) throws Refusal {
        List<String> notes = new ArrayList<>();
        List<String> written = BoardFileLexer.words(line);
        boolean markedOurs = written.get(0).startsWith(CommandWord.OURS);
        List<String> words = markedOurs ? ours(written) : written;
        String first = words.get(0).toLowerCase(Locale.ROOT);
        if ((first.equals("left") || first.equals("right")) && words.size() > 1
                && words.get(1).equalsIgnoreCase("flipper")) {
            CommandWord word = first.equals("left") ? CommandWord.LEFT_FLIPPER : CommandWord.RIGHT_FLIPPER;
            notes.add("'" + words.get(0) + " " + words.get(1) + "' read as " + word.spelling());
            return new Parsed(parse(word, words.subList(2, words.size()), notes), notes);
        }
        if (first.equals("flipper")) {
            return new Parsed(parse(genericFlipper(words.subList(1, words.size()), notes),
                    words.subList(1, words.size()), notes), notes);
        }
        if (first.equals("color") || first.equals("colour")) {
            return new Parsed(colour(words, notes), notes);
        }
        PeerGizmo peer = markedOurs ? null : PEER_GIZMOS.get(first);
        if (peer != null && words.size() == 1 + peer.word().argumentCount()) {
            notes.add("'" + words.get(0) + "' of another implementation read as " + peer.word().written() + ": "
                    + peer.meaning());
            return new Parsed(parse(peer.word(), words.subList(1, words.size()), notes), notes);
        }
        if (peer != null) {
            throw peerArguments(words, peer.word());
        }
        if (!markedOurs && PEER_EXTENSIONS.contains(first)) {
            throw unknownCommand(words);   // another's extension, though one of ours has its name (tomcurran's Gate)
        }
        CommandWord word = CommandWord.lookup(words.get(0)).orElseThrow(() -> unknownCommand(words));
        if (word.ours() && !markedOurs) {
            throw new Refusal(word.spelling() + " is an addition of this game to the format: it is written "
                    + word.written() + ", which other implementations skip as a comment");
        }
        List<String> args = words.subList(1, words.size());
        boolean ordering = word == CommandWord.KEY_CONNECT || word == CommandWord.CONNECT;
        if (ordering && markedOurs && args.size() > word.argumentCount()) {
            Order order = OrderWords.parse(args.subList(word.argumentCount(), args.size()));
            return new Parsed(withOrder(parse(word, args.subList(0, word.argumentCount()), notes), order), notes);
        }
        if (ordering && !markedOurs && args.size() > word.argumentCount()
                && OrderWords.startsAnOrder(args.get(word.argumentCount()))
                && !args.get(word.argumentCount()).equals(args.get(word.argumentCount() - 1))) {
            throw new Refusal("an action or a delay is an addition of this game to the format: the line is written "
                    + CommandWord.OURS + word.spelling() + ", which other implementations skip as a comment");
        }
        return new Parsed(parse(word, args, notes), notes);
    }

    /**
     * A {@code #@} line without its mark: one of our commands, or a standard one about something only we have (the
     * extension gizmos), which a loader of the standard format must skip with it.
     */
    private static List<String> ours(List<String> written) throws Refusal {
        String word = written.get(0).substring(CommandWord.OURS.length());
        if (CommandWord.lookup(word).isEmpty()) {
            throw new Refusal("unknown command '" + written.get(0) + "' (a line starting #@ and a word is a command"
                    + " of this game: " + Arrays.stream(CommandWord.values()).filter(CommandWord::ours)
                    .map(CommandWord::written).collect(Collectors.joining(", ")) + ")");
        }
        List<String> words = new ArrayList<>(written);
        words.set(0, word);
        return words;
    }

    /** The connection or key binding with the order written after its target. */
    private static Command withOrder(Command command, Order order) {
        if (command instanceof Command.KeyConnect k) {
            return new Command.KeyConnect(k.keyCode(), k.edge(), k.gizmo(), order);
        }
        Command.Connect c = (Command.Connect) command;
        return new Command.Connect(c.source(), c.target(), order);
    }

    private static Command parse(CommandWord word, List<String> given, List<String> notes) throws Refusal {
        refuseMit3d(word, given);
        List<String> args = given;
        if (word == CommandWord.BALL && args.size() == 3) {
            notes.add("no velocity given: the ball starts at rest");
            args = List.of(args.get(0), args.get(1), args.get(2), "0", "0");
        }
        if (word == CommandWord.PLUNGER && (args.size() == 1 || args.size() == 2)) {
            List<String> defaults = List.of(Decimals.format(Plunger.DEFAULT_FULL_SPEED),
                    Decimals.format(Plunger.DEFAULT_PULL_SECONDS));
            List<String> padded = new ArrayList<>(args);
            padded.addAll(defaults.subList(args.size() - 1, 2));
            args = padded;
        }
        if (word == CommandWord.NUDGE && (args.size() == 0 || args.size() == 1)) {
            List<String> padded = new ArrayList<>(args.isEmpty()
                    ? List.of(Decimals.format(Nudge.DEFAULT.speed())) : args);
            padded.addAll(List.of(Integer.toString(Nudge.DEFAULT.leftKey()), Integer.toString(Nudge.DEFAULT.rightKey()),
                    Integer.toString(Nudge.DEFAULT.upKey())));
            args = padded;
        }
        if (word == CommandWord.KEY_CONNECT && args.size() == 5 && args.get(3).equals(args.get(4))) {
            notes.add("target " + args.get(4) + " written twice: read once");
            args = args.subList(0, 4);
        }
        if (args.size() != word.argumentCount()) {
            throw new Refusal("wrong number of arguments: " + word.written() + " takes " + word.argumentCount()
                    + " (" + word.usage() + "), found " + args.size());
        }
        return switch (word) {
            case ABSORBER -> absorber(args, notes);
            case BALL -> new Command.AddBall(args.get(0), ballCoordinate("x", args.get(1)),
                    ballCoordinate("y", args.get(2)), number("vx", args.get(3)), number("vy", args.get(4)));
            case ROTATE -> new Command.Rotate(args.get(0));
            case DELETE -> new Command.Delete(args.get(0));
            case MOVE -> new Command.Move(args.get(0), number("x", args.get(1)), number("y", args.get(2)));
            case CONNECT -> new Command.Connect(TriggerSource.named(args.get(0)), args.get(1));
            case KEY_CONNECT -> keyConnect(args, notes);
            case CELL_OPEN -> new Command.CellOpen(args.get(0));
            case FLIPPER_STATE -> new Command.FlipperState(args.get(0), number("angle", args.get(1)),
                    direction(args.get(2)));
            case FACTOR -> new Command.Factor(args.get(0), number("factor", args.get(1)));
            case PLUNGER -> new Command.MakePlunger(args.get(0), new Plunger(number("full-pull speed", args.get(1)),
                    number("pull seconds", args.get(2))));
            case PAIR -> new Command.Pair(args.get(0), args.get(1));
            case SPINNER_SPEED -> new Command.SpinnerSpeed(args.get(0), number("turns per second", args.get(1)));
            case SPINNER_STATE -> new Command.SpinnerState(args.get(0), number("angle", args.get(1)),
                    running(args.get(2)));
            case SPAWN_VELOCITY -> new Command.SpawnVelocity(args.get(0), number("vx", args.get(1)),
                    number("vy", args.get(2)));
            case GRAVITY -> new Command.Gravity(number("gravity", args.get(0)));
            case FRICTION -> new Command.Friction(number("mu", args.get(0)), number("mu2", args.get(1)));
            case BALLS -> new Command.BallsPerGame(wholeNumber("balls per game", args.get(0)));
            case EXTRA_BALL -> new Command.ExtraBall(score(args.get(0)));
            case DRAIN -> new Command.Drain(args.get(0));
            case POINTS -> new Command.Points(args.get(0), wholeNumber("points", args.get(1)));
            case NUDGE -> new Command.NudgeLine(nudge(args, notes));
            case TILT -> new Command.TiltLine(tilt(args));
            case BALL_SAVE -> new Command.BallSave(number("ball save seconds", args.get(0)));
            case COLOUR -> throw new IllegalStateException("colours are read by colour(), in any spelling");
            // Every other word adds a gizmo of its kind on one cell (CommandWord.of says which: a word that adds none
            // throws there).
            default -> new Command.AddGizmo(word.kind(), args.get(0), cell("x", args.get(1)), cell("y", args.get(2)));
        };
    }

    private static boolean direction(String word) throws Refusal {
        if (word.equalsIgnoreCase("up")) {
            return true;
        }
        if (word.equalsIgnoreCase("down")) {
            return false;
        }
        throw new Refusal("a flipper's direction is up or down, not " + word);
    }

    private static boolean running(String word) throws Refusal {
        if (word.equalsIgnoreCase("running")) {
            return true;
        }
        if (word.equalsIgnoreCase("stopped")) {
            return false;
        }
        throw new Refusal("a spinner is running or stopped, not " + word);
    }

    /** {@code Flipper <name> <x> <y>}: the side is in the name, LF... or RF... */
    private static CommandWord genericFlipper(List<String> args, List<String> notes) throws Refusal {
        String name = args.isEmpty() ? "" : args.get(0).toUpperCase(Locale.ROOT);
        CommandWord word;
        if (name.startsWith("LF")) {
            word = CommandWord.LEFT_FLIPPER;
        } else if (name.startsWith("RF")) {
            word = CommandWord.RIGHT_FLIPPER;
        } else {
            throw new Refusal("a Flipper of no known side: read only when its name starts with LF (left) or RF"
                    + " (right)");
        }
        notes.add("Flipper " + args.get(0) + " read as " + word.spelling() + " (from its name)");
        return word;
    }

    /** The corners in any order: each axis from its smaller to its larger number. */
    private static Command absorber(List<String> args, List<String> notes) throws Refusal {
        int x1 = cell("x1", args.get(1));
        int y1 = cell("y1", args.get(2));
        int x2 = cell("x2", args.get(3));
        int y2 = cell("y2", args.get(4));
        Command.AddAbsorber absorber = new Command.AddAbsorber(args.get(0), Math.min(x1, x2), Math.min(y1, y2),
                Math.max(x1, x2), Math.max(y1, y2));
        if (x2 < x1 || y2 < y1) {
            notes.add("corners given in reverse order: read as " + absorber.toLine());
        }
        return absorber;
    }

    /**
     * Colour or Color (any case) with name r g b, name #rrggbb, or name and a signed Java ARGB int (alpha
     * ignored); a note for every spelling but our own, Colour name r g b.
     */
    private static Command colour(List<String> words, List<String> notes) throws Refusal {
        List<String> args = words.subList(1, words.size());
        Command.Colour colour;
        if (args.size() == 4) {
            colour = new Command.Colour(args.get(0), new Rgb(channel("red", args.get(1)),
                    channel("green", args.get(2)), channel("blue", args.get(3))));
        } else if (args.size() == 2 && HEX_COLOUR.matcher(args.get(1)).matches()) {
            colour = new Command.Colour(args.get(0), Rgb.of(Integer.parseInt(args.get(1).substring(1), 16)));
        } else if (args.size() == 2) {
            double argb = Decimals.parse(args.get(1)).orElse(Double.NaN);
            if (argb != Math.rint(argb) || argb < Integer.MIN_VALUE || argb > 0xffffffffL) {
                throw new Refusal("colour '" + args.get(1) + "' is neither #rrggbb nor a 32-bit ARGB number");
            }
            colour = new Command.Colour(args.get(0), Rgb.of((int) (long) argb));
        } else {
            throw new Refusal("wrong number of arguments: " + CommandWord.COLOUR.spelling() + " takes <name> and"
                    + " <red> <green> <blue>, #rrggbb or an ARGB number; found " + args.size() + " arguments");
        }
        if (args.size() != 4 || words.get(0).equalsIgnoreCase("color")) {
            notes.add("read as " + colour.toLine());
        }
        return colour;
    }

    private static int channel(String what, String word) throws Refusal {
        int value = wholeNumber(what, word);
        if (value < 0 || value > 255) {
            throw new Refusal(what + " " + word + " is not a colour channel 0..255");
        }
        return value;
    }

    private static Command keyConnect(List<String> args, List<String> notes) throws Refusal {
        if (!args.get(0).equalsIgnoreCase("key")) {
            throw new Refusal("expected the word 'key' after KeyConnect, found '" + args.get(0) + "'");
        }
        int keyCode = keyCode(args.get(1), notes);
        String direction = args.get(2).toLowerCase(Locale.ROOT);
        KeyEdge edge = switch (direction) {
            case "down", "ondown" -> KeyEdge.DOWN;
            case "up", "onup" -> KeyEdge.UP;
            case "change" -> KeyEdge.CHANGE;
            default -> throw new Refusal("bad direction '" + args.get(2) + "': expected down, up or change");
        };
        if (direction.startsWith("on")) {
            notes.add("'" + args.get(2) + "' read as " + edge.name().toLowerCase(Locale.ROOT));
        }
        return new Command.KeyConnect(keyCode, edge, args.get(3));
    }

    /** A KeyEvent code, or a KeyEvent key name (Space, "Left", q), quoted or not. */
    private static int keyCode(String word, List<String> notes) throws Refusal {
        String unquoted = word.length() >= 2 && (word.startsWith("\"") && word.endsWith("\"")
                || word.startsWith("'") && word.endsWith("'")) ? word.substring(1, word.length() - 1) : word;
        if (Decimals.parse(unquoted).isEmpty()) {
            OptionalInt named = KeyCodes.named(unquoted);
            if (named.isEmpty()) {
                throw new Refusal("unknown key " + word + ": neither a key code nor a java.awt.event.KeyEvent key"
                        + " name (VK_ without the prefix, such as Space or Q)");
            }
            notes.add("key " + word + " read as key code " + named.getAsInt());
            return named.getAsInt();
        }
        int keyCode = wholeNumber("key code", unquoted);
        if (!KeyCodes.isKnown(keyCode)) {
            throw new Refusal("unknown key code " + keyCode + " (not a java.awt.event.KeyEvent VK_ code)");
        }
        return keyCode;
    }

    /** The MIT 6.170 3-D variant: corners and positions with a z, rotations about two axes, a gravity vector. */
    private static void refuseMit3d(CommandWord word, List<String> args) throws Refusal {
        String form = switch (word) {
            case ABSORBER -> args.size() == 7 && allNumbers(args.subList(1, 7)) ? "an absorber with x y z corners" : null;
            case BALL -> args.size() == 8 && allNumbers(args.subList(1, 8)) ? "a ball with x y z and its velocity" : null;
            case ROTATE -> args.size() == 2 && AXES.matcher(args.get(1)).matches() ? "a rotation in a plane of axes"
                    : null;
            case GRAVITY -> args.size() == 3 && allNumbers(args) ? "a gravity vector" : null;
            default -> null;
        };
        if (form != null) {
            throw mit3d(form);
        }
    }

    /** A peer's gizmo line with other arguments than ours takes: a portal with its exit's cell is named as such. */
    private static Refusal peerArguments(List<String> words, CommandWord word) {
        int found = words.size() - 1;
        String why = word == CommandWord.PORTAL && found == 5 && allNumbers(words.subList(2, 6))
                ? ": a portal and the cell of its exit on one line, another implementation's form whose exit has no name;"
                        + " this game's portals are two gizmos, each #@Portal <name> <x> <y>, joined by #@Pair"
                : "";
        return new Refusal("wrong number of arguments: '" + words.get(0) + "' of another implementation is read as "
                + word.written() + ", which takes " + word.argumentCount() + " (" + word.usage() + "), found " + found
                + why);
    }

    private static Refusal mit3d(String form) {
        return new Refusal("an MIT 6.170 3-D form (" + form + ")" + NOT_THE_FORMAT);
    }

    /**
     * Why a first word is not known: a command of another implementation's extension, an MIT 3-D gizmo, or an
     * unknown command, with the nearest command of the format when the word is close to one (a misspelling).
     */
    private static Refusal unknownCommand(List<String> words) {
        String word = words.get(0);
        String lowerCase = word.toLowerCase(Locale.ROOT);
        List<String> args = words.subList(1, words.size());
        if (MIT_3D_GIZMOS.contains(lowerCase) && args.size() == 5 && allNumbers(args.subList(1, 5))) {
            return mit3d("a gizmo with x y z and a size");
        }
        if (PEER_EXTENSIONS.contains(lowerCase)) {
            boolean named = !args.isEmpty() && Decimals.parse(args.get(0)).isEmpty()
                    && WORD.matcher(word).matches() && !lowerCase.endsWith("connect");
            return new Refusal((named ? word + " " + args.get(0) : word) + ": " + EXTENSION);
        }
        return new Refusal("unknown command '" + word + "'"
                + NearestWord.among(word, CommandWord.spellings()).map(w -> " (did you mean " + w + "?)").orElse(""));
    }

    private static boolean allNumbers(List<String> words) {
        return words.stream().allMatch(w -> Decimals.parse(w).isPresent());
    }

    /** A gizmo coordinate: a whole number of cells, also when written as a decimal such as 7.0. */
    private static int cell(String what, String word) throws Refusal {
        double value = number(what, word);
        if (value != Math.rint(value)) {
            throw new Refusal(what + " coordinate " + word + " is not a whole cell: gizmos sit on whole cells, the"
                    + " format has no fractional cells");
        }
        if (Math.abs(value) > COORDINATE_LIMIT) {
            throw new Refusal(what + " coordinate " + word + " is outside the board");
        }
        refusePixels(what, word, value);
        return (int) value;
    }

    private static double ballCoordinate(String what, String word) throws Refusal {
        double value = number(what, word);
        refusePixels(what, word, value);
        return value;
    }

    private static void refusePixels(String what, String word, double value) throws Refusal {
        if (Math.abs(value) >= PIXEL_COORDINATES_FROM && Math.abs(value) <= COORDINATE_LIMIT) {
            throw new Refusal(what + " coordinate " + word + " is far outside the " + Board.SIZE + "x" + Board.SIZE
                    + " board: pixel coordinates, it seems, but the format counts in L (cells)");
        }
    }

    /** A score: a whole number, up to far more than any game reaches. */
    private static Nudge nudge(List<String> args, List<String> notes) throws Refusal {
        try {
            return new Nudge(number("nudge speed", args.get(0)), keyCode(args.get(1), notes),
                    keyCode(args.get(2), notes), keyCode(args.get(3), notes));
        } catch (IllegalArgumentException refused) {
            throw new Refusal(refused.getMessage());
        }
    }

    private static Tilt tilt(List<String> args) throws Refusal {
        try {
            return new Tilt(wholeNumber("nudges", args.get(0)), number("seconds", args.get(1)));
        } catch (IllegalArgumentException refused) {
            throw new Refusal(refused.getMessage());
        }
    }

    private static long score(String word) throws Refusal {
        double value = number("score", word);
        if (value != Math.rint(value) || Math.abs(value) > 1e15) {
            throw new Refusal("score " + word + " is not a whole number");
        }
        return (long) value;
    }

    private static int wholeNumber(String what, String word) throws Refusal {
        double value = number(what, word);
        if (value != Math.rint(value) || Math.abs(value) > Integer.MAX_VALUE) {
            throw new Refusal(what + " " + word + " is not a whole number");
        }
        return (int) value;
    }

    private static double number(String what, String word) throws Refusal {
        OptionalDouble value = Decimals.parse(word);
        if (value.isEmpty()) {
            throw new Refusal(what + " '" + word + "' is not a number");
        }
        return value.getAsDouble();
    }
}
