package gizmoball.boardfile;

import static gizmoball.boardfile.ArgumentWords.ballCoordinate;
import static gizmoball.boardfile.ArgumentWords.cell;
import static gizmoball.boardfile.ArgumentWords.channel;
import static gizmoball.boardfile.ArgumentWords.direction;
import static gizmoball.boardfile.ArgumentWords.keyCode;
import static gizmoball.boardfile.ArgumentWords.number;
import static gizmoball.boardfile.ArgumentWords.nudge;
import static gizmoball.boardfile.ArgumentWords.running;
import static gizmoball.boardfile.ArgumentWords.score;
import static gizmoball.boardfile.ArgumentWords.tilt;
import static gizmoball.boardfile.ArgumentWords.wholeNumber;
import static gizmoball.boardfile.PeerDialects.genericFlipper;
import static gizmoball.boardfile.PeerDialects.peerArguments;
import static gizmoball.boardfile.PeerDialects.allNumbers;
import static gizmoball.boardfile.PeerDialects.mit3d;
import static gizmoball.boardfile.PeerDialects.unknownCommand;

import gizmoball.model.KeyEdge;
import gizmoball.model.game.Nudge;
import gizmoball.model.gizmo.Order;
import gizmoball.model.gizmo.Plunger;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.loop.TriggerSource;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

/**
 * Turns one command line into a {@link Command}, or says precisely why it cannot. Besides the canonical form it
 * reads the spellings other implementations write (two-word and generic flippers, colours, key names, ondown,
 * reversed absorber corners, balls without velocity...), each with a note saying how it was understood. Each argument
 * word is read by {@link ArgumentWords}; what other implementations write, ours or not, is known to {@link PeerDialects}.
 */
final class CommandParser {
    private static final Pattern AXES = Pattern.compile("[XYZ]{2}", Pattern.CASE_INSENSITIVE);
    private static final Pattern HEX_COLOUR = Pattern.compile("#[0-9a-fA-F]{6}");

    private CommandParser() {
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
        Optional<CommandWord> twoWords = PeerDialects.twoWordFlipper(words, notes);
        if (twoWords.isPresent()) {
            return new Parsed(parse(twoWords.get(), words.subList(2, words.size()), notes), notes);
        }
        if (first.equals("flipper")) {
            return new Parsed(parse(genericFlipper(words.subList(1, words.size()), notes),
                    words.subList(1, words.size()), notes), notes);
        }
        if (first.equals("color") || first.equals("colour")) {
            return new Parsed(colour(words, notes), notes);
        }
        PeerDialects.PeerGizmo peer = markedOurs ? null : PeerDialects.gizmo(first).orElse(null);
        if (peer != null && words.size() == 1 + peer.word().argumentCount()) {
            notes.add("'" + words.get(0) + "' of another implementation read as " + peer.word().written() + ": "
                    + peer.meaning());
            return new Parsed(parse(peer.word(), words.subList(1, words.size()), notes), notes);
        }
        if (peer != null) {
            throw peerArguments(words, peer.word());
        }
        if (!markedOurs && PeerDialects.isExtension(first)) {
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
            case BALLS -> new GameLine.BallsPerGame(wholeNumber("balls per game", args.get(0)));
            case EXTRA_BALL -> new GameLine.ExtraBall(score(args.get(0)));
            case DRAIN -> new GameLine.Drain(args.get(0));
            case POINTS -> new GameLine.Points(args.get(0), wholeNumber("points", args.get(1)));
            case NUDGE -> new GameLine.NudgeLine(nudge(args, notes));
            case TILT -> new GameLine.TiltLine(tilt(args));
            case BALL_SAVE -> new GameLine.BallSave(number("ball save seconds", args.get(0)));
            case COLOUR -> throw new IllegalStateException("colours are read by colour(), in any spelling");
            // Every other word adds a gizmo of its kind (CommandWord.of says which: a word that adds none throws there),
            // on one cell or, for a kind sized by its corners, over them.
            default -> word.addsSizedByCorners() ? sizedByCorners(args, notes)
                    : new Command.AddGizmo(word.kind(), args.get(0), cell("x", args.get(1)), cell("y", args.get(2)));
        };
    }

    /** A gizmo sized by its corners (an absorber), in any order: each axis from its smaller to its larger number. */
    private static Command sizedByCorners(List<String> args, List<String> notes) throws Refusal {
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

    /** The MIT 6.170 3-D variant: corners and positions with a z, rotations about two axes, a gravity vector. */
    private static void refuseMit3d(CommandWord word, List<String> args) throws Refusal {
        String form = switch (word) {
            case BALL -> args.size() == 8 && allNumbers(args.subList(1, 8)) ? "a ball with x y z and its velocity" : null;
            case ROTATE -> args.size() == 2 && AXES.matcher(args.get(1)).matches() ? "a rotation in a plane of axes"
                    : null;
            case GRAVITY -> args.size() == 3 && allNumbers(args) ? "a gravity vector" : null;
            default -> word.addsSizedByCorners() && args.size() == 7 && allNumbers(args.subList(1, 7))
                    ? word.kind().withArticle() + " with x y z corners" : null;
        };
        if (form != null) {
            throw mit3d(form);
        }
    }
}
