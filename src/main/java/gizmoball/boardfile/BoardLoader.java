package gizmoball.boardfile;

import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.loop.TriggerSource;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * Builds a new board from board-file text, command by command through the board's editing operations.
 * A command the board refuses (overlap, outside, duplicate or unknown name...) becomes an error on its line,
 * just like a syntax error; the remaining commands are still applied so that one load reports every problem.
 *
 * <p>What other implementations write is read as they meant it, each with a note: a command naming a gizmo or
 * ball that a later line defines waits for that line and is applied right after it (some savers write the
 * connections before the gizmos); a ball whose name another ball already has gets a fresh name; balls placed on
 * each other are loaded (the loop lets them pass through each other until they separate); a bare {@code Connect}
 * between two portals (tomcurran's and d-g-n's way of linking them; ours is written {@code #@Connect}) pairs them.
 */
final class BoardLoader {

    /** The commands that name gizmos or balls instead of adding them. */
    private static final Set<CommandWord> REFERENCING = Set.of(CommandWord.ROTATE, CommandWord.DELETE,
            CommandWord.MOVE, CommandWord.CONNECT, CommandWord.KEY_CONNECT, CommandWord.COLOUR,
            CommandWord.FLIPPER_STATE, CommandWord.DRAIN, CommandWord.POINTS, CommandWord.CELL_OPEN, CommandWord.PAIR,
            CommandWord.PLUNGER);

    private BoardLoader() {
    }

    /** A new board with every applicable command, an error for each other line, and the notes. */
    static LoadResult loadSkippingBadLines(String source, String content) {
        return new Run(source, ParsedFile.parse(source, content)).result(content);
    }

    /** A new board, only if every line of the file is good. */
    static Board load(String source, String content) throws BoardFileException {
        LoadResult result = loadSkippingBadLines(source, content);
        if (!result.skippedLines().isEmpty()) {
            throw new BoardFileException(result.skippedLines());
        }
        return result.board();
    }

    /** One load: the board being built, what was found so far, and the commands waiting for a later line. */
    private static final class Run {
        private final String source;
        private final Board board = new Board();
        private final List<BoardFileError> errors = new ArrayList<>();
        private final List<BoardFileNote> notes = new ArrayList<>();
        /** Every name the file defines -> the numbers of the lines that define it. */
        private final Map<String, List<Integer>> definitions = new HashMap<>();
        /** Ball name -> the line that placed that ball, for the note on a ball renamed because of it. */
        private final Map<String, Integer> ballLines = new HashMap<>();
        /** In file order. */
        private final List<ParsedFile.Line> waiting = new ArrayList<>();
        /** Name -> the line that would have defined it but was refused, to say so where the name is used. */
        private final Map<String, Integer> refusedDefinitions = new HashMap<>();

        Run(String source, ParsedFile parsed) {
            this.source = source;
            errors.addAll(parsed.errors());
            for (BoardFileError error : parsed.errors()) {
                // A refused line that would add something (an extension gizmo, a malformed Square...) names it
                // second; the reference commands name other things there.
                List<String> words = BoardFileLexer.words(error.text());
                boolean references = CommandWord.lookup(words.get(0)).map(REFERENCING::contains).orElse(false);
                if (words.size() > 1 && !references) {
                    refusedDefinitions.putIfAbsent(words.get(1), error.line());
                }
            }
            for (ParsedFile.Line line : parsed.commands()) {
                line.command().defines().ifPresent(name ->
                        definitions.computeIfAbsent(name, n -> new ArrayList<>()).add(line.line().number()));
            }
            for (ParsedFile.Line line : parsed.commands()) {
                line.notes().forEach(note -> note(line, note));
                if (mustWait(line)) {
                    waiting.add(line);
                } else {
                    apply(line);
                }
            }
            // What still waits names something never defined (or whose definition was refused): applied now, in
            // file order, it is refused at its own line.
            List<ParsedFile.Line> neverDefined = List.copyOf(waiting);
            waiting.clear();
            neverDefined.forEach(this::apply);
        }

        LoadResult result(String content) {
            errors.sort(Comparator.comparingInt(BoardFileError::line));
            notes.sort(Comparator.comparingInt(BoardFileNote::line));
            return new LoadResult(board, errors, notes, new AuthoredText(content, board, errors));
        }

        /**
         * A command waits when it names something a later line defines, or something an earlier waiting command
         * names (so that commands on one name keep their order: a Delete, a Move after a Move).
         */
        private boolean mustWait(ParsedFile.Line line) {
            Set<String> waitedOn = new HashSet<>();
            waiting.forEach(w -> waitedOn.addAll(w.command().references()));
            return line.command().references().stream()
                    .anyMatch(name -> waitedOn.contains(name) || !exists(name) && definedAfter(name, line));
        }

        private boolean definedAfter(String name, ParsedFile.Line line) {
            return definitions.getOrDefault(name, List.of()).stream().anyMatch(n -> n > line.line().number());
        }

        private boolean exists(String name) {
            return board.gizmo(name).isPresent() || board.ball(name).isPresent();
        }

        private void apply(ParsedFile.Line line) {
            try {
                if (line.command() instanceof Command.AddBall ball) {
                    addBall(line, ball);
                } else if (peersLink(line) != null) {
                    pairLinked(line, peersLink(line));
                } else {
                    line.command().applyTo(board);
                }
            } catch (BoardEditException refused) {
                String reason = refused.getMessage() + line.command().references().stream()
                        .filter(name -> !exists(name) && refusedDefinitions.containsKey(name)).findFirst()
                        .map(name -> "; line " + refusedDefinitions.get(name) + ", which would define " + name
                                + ", was refused").orElse("");
                errors.add(BoardFileError.at(source, line.line(), reason));
                line.command().defines().ifPresent(name -> refusedDefinitions.putIfAbsent(name, line.line().number()));
                return;
            }
            if (line.command().defines().isPresent()) {
                release(line);
            }
        }

        /** After {@code defining} added its gizmo or ball: the waiting commands that can go now, in file order. */
        private void release(ParsedFile.Line defining) {
            for (Optional<ParsedFile.Line> ready = nextReady(); ready.isPresent(); ready = nextReady()) {
                ParsedFile.Line line = ready.get();
                waiting.remove(line);
                note(line, "applied after line " + defining.line().number() + ", which defines "
                        + defining.command().defines().orElseThrow());
                apply(line);
            }
        }

        /** The first waiting command whose names all exist and that no earlier waiting command shares a name with. */
        private Optional<ParsedFile.Line> nextReady() {
            Set<String> stillWaitedOn = new HashSet<>();
            for (ParsedFile.Line line : waiting) {
                List<String> names = line.command().references();
                if (names.stream().allMatch(this::exists) && names.stream().noneMatch(stillWaitedOn::contains)) {
                    return Optional.of(line);
                }
                stillWaitedOn.addAll(names);
            }
            return Optional.empty();
        }

        /** A bare connection from a portal to a portal (another implementation's link), or null. */
        private Command.Connect peersLink(ParsedFile.Line line) {
            return line.command() instanceof Command.Connect c && !line.line().text().strip().startsWith(CommandWord.OURS)
                    && c.source() instanceof TriggerSource.OfGizmo from && portal(from.gizmo()) != null
                    && portal(c.target()) != null ? c : null;
        }

        /** The pair of the gizmo of that name if it is one that is paired (a portal), or null. */
        private Setting.Pair portal(String name) {
            return board.gizmo(name).map(Gizmo::setting).filter(Setting.Pair.class::isInstance)
                    .map(Setting.Pair.class::cast).orElse(null);
        }

        /**
         * Pairs two portals a peer's connection links, where neither has a pair yet: a portal of this game has one,
         * both ways, where the peers' links go one way and a portal may have several (refused, saying so).
         */
        private void pairLinked(ParsedFile.Line line, Command.Connect link) {
            String from = ((TriggerSource.OfGizmo) link.source()).gizmo();
            String to = link.target();
            if (portal(from).portal().equals(Optional.of(to))) {
                throw new BoardEditException(from + " and " + to + " are paired already");
            }
            for (String name : List.of(from, to)) {
                Optional<String> pair = portal(name).portal();
                if (pair.isPresent()) {
                    throw new BoardEditException("portal " + name + " is paired with " + pair.get() + " already: a"
                            + " portal of this game has one pair, a ball going through it both ways");
                }
            }
            new Command.Pair(from, to).applyTo(board);
            note(line, "'Connect' from a portal to a portal, another implementation's link, read as "
                    + new Command.Pair(from, to).toLine() + ": a ball entering either leaves by the other (in the game"
                    + " that wrote it, from " + from + " to " + to + ")");
        }

        /** A ball named like an earlier ball gets a fresh name; one placed on other balls is loaded with a note. */
        private void addBall(ParsedFile.Line line, Command.AddBall ball) {
            Command.AddBall placed = ball;
            if (board.ball(ball.name()).isPresent()) {
                placed = ball.named(freshName(ball.name()));
            }
            List<String> overlapped = board.addBallOverlappingBalls(placed.name(), placed.x(), placed.y(),
                    placed.vx(), placed.vy());
            if (placed != ball) {
                note(line, "ball " + ball.name() + " renamed " + placed.name() + ": line "
                        + ballLines.get(ball.name()) + " has a ball of that name");
            }
            ballLines.putIfAbsent(placed.name(), line.line().number());
            for (String other : overlapped) {
                note(line, "ball " + placed.name() + " overlaps ball " + other + ": loaded; the two pass through"
                        + " each other until they separate");
            }
        }

        /** name_2, name_3, ...: the first that is neither on the board nor defined anywhere in the file. */
        private String freshName(String name) {
            for (int n = 2; ; n++) {
                String candidate = name + "_" + n;
                if (!exists(candidate) && !definitions.containsKey(candidate)) {
                    return candidate;
                }
            }
        }

        private void note(ParsedFile.Line line, String note) {
            notes.add(BoardFileNote.at(source, line.line(), note));
        }
    }
}
