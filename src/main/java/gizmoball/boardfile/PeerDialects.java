package gizmoball.boardfile;

import gizmoball.model.gizmo.Setting;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.regex.Pattern;

/**
 * What other implementations write that the format does not have: their gizmos that are ours as well (read, with a
 * note of what they mean here), their extensions and the MIT 6.170 3-D forms (refused by name), their generic
 * flippers; and the nearest word of the format for a misspelt one.
 */
final class PeerDialects {
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
    record PeerGizmo(CommandWord word, String meaning) {
    }

    private static final Pattern WORD = Pattern.compile("[A-Za-z][A-Za-z0-9_]*");

    private PeerDialects() {
    }

    /** The peer's gizmo that a line's first word (in lower case) names, unless the line is marked as ours. */
    static Optional<PeerGizmo> gizmo(String first) {
        return Optional.ofNullable(PEER_GIZMOS.get(first));
    }

    /** Left Flipper or Right Flipper (two words, any case), read as the one word of the format, with a note. */
    static Optional<CommandWord> twoWordFlipper(List<String> words, List<String> notes) {
        String first = words.get(0).toLowerCase(Locale.ROOT);
        if ((first.equals("left") || first.equals("right")) && words.size() > 1
                && words.get(1).equalsIgnoreCase("flipper")) {
            CommandWord word = first.equals("left") ? CommandWord.LEFT_FLIPPER : CommandWord.RIGHT_FLIPPER;
            notes.add("'" + words.get(0) + " " + words.get(1) + "' read as " + word.spelling());
            return Optional.of(word);
        }
        return Optional.empty();
    }

    /** Whether the first word (in lower case) is a command of another implementation's own. */
    static boolean isExtension(String first) {
        return PEER_EXTENSIONS.contains(first);
    }

    /** {@code Flipper <name> <x> <y>}: the side is in the name, LF... or RF... */
    static CommandWord genericFlipper(List<String> args, List<String> notes) throws Refusal {
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

    /** A peer's gizmo line with other arguments than ours takes: a portal with its exit's cell is named as such. */
    static Refusal peerArguments(List<String> words, CommandWord word) {
        int found = words.size() - 1;
        String why = word == CommandWord.PORTAL && found == 5 && allNumbers(words.subList(2, 6))
                ? ": a portal and the cell of its exit on one line, another implementation's form whose exit has no name;"
                        + " this game's portals are two gizmos, each #@Portal <name> <x> <y>, joined by #@Pair"
                : "";
        return new Refusal("wrong number of arguments: '" + words.get(0) + "' of another implementation is read as "
                + word.written() + ", which takes " + word.argumentCount() + " (" + word.usage() + "), found " + found
                + why);
    }

    static Refusal mit3d(String form) {
        return new Refusal("an MIT 6.170 3-D form (" + form + ")" + NOT_THE_FORMAT);
    }

    /**
     * Why a first word is not known: a command of another implementation's extension, an MIT 3-D gizmo, or an
     * unknown command, with the nearest command of the format when the word is close to one (a misspelling).
     */
    static Refusal unknownCommand(List<String> words) {
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

    static boolean allNumbers(List<String> words) {
        return words.stream().allMatch(w -> Decimals.parse(w).isPresent());
    }
}
