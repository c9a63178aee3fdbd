package gizmoball.boardfile;

import gizmoball.model.Board;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;

/**
 * Writes an edited board over the text it was loaded from, keeping what the author wrote. Each line of the text
 * is a comment, a blank line, a line the load left out, or a command; a command states a {@link Subject} (a gizmo
 * itself, its rotation, a connection...) or is history (a Move or a Delete), which acts on things.
 * <ul>
 *   <li>The lines of a subject that the edits did not change stay as written; so do comments and blank lines.</li>
 *   <li>A subject that changed is written canonically where its first line was, and its other lines go; so do
 *       the history lines of a thing that changed (its new line says where it is now).</li>
 *   <li>What the text had no line for is added after the last line of its own sort (a new gizmo after the last
 *       gizmo line, a {@code #@KeyConnect} after the last key binding), or, when there is none, where the canonical
 *       order puts it among the lines of other sorts; never before the line defining a thing it names.</li>
 *   <li>The lines the load left out go.</li>
 * </ul>
 * The result is loaded again before it is offered. Its connections and key bindings may come in another order (a
 * connection taken away and made again keeps the line it had), everything else must be exactly the edited board.
 * If it is not, or the result does not load cleanly (a text whose lines act on each other in ways the rules above
 * do not follow), the canonical form is written instead, and the comments and blank lines it would lose are
 * counted for the question asked before saving.
 */
final class LineMerge {
    private static final char BYTE_ORDER_MARK = '\uFEFF';

    /**
     * One line of the new text: as written (with the CR of a CR LF line), or new (which gets the text's line end);
     * the command it holds, if any, for placing new lines.
     */
    private record Entry(String text, Optional<Command> command, boolean isNew) {
    }

    private final Map<Subject, List<String>> before = new LinkedHashMap<>();
    private final Map<Subject, List<Command>> after = new LinkedHashMap<>();
    /** The sorts of line (gizmos, rotations, ..., friction) in the order the canonical form writes them. */
    private final Map<Class<?>, Integer> sortOrder = new HashMap<>();
    private final List<Entry> entries = new ArrayList<>();
    private final Set<Subject> written = new HashSet<>();
    /** What ends a new line before its LF: a CR in a text of CR LF lines. */
    private String carriageReturn = "";
    private int badLines;
    private int comments;
    private int blankLines;

    private LineMerge(List<Command> loaded, List<Command> edited) {
        loaded.forEach(c -> before.computeIfAbsent(c.subject(), s -> new ArrayList<>()).add(c.toLine()));
        edited.forEach(c -> after.computeIfAbsent(c.subject(), s -> new ArrayList<>()).add(c));
        edited.forEach(c -> sortOrder.putIfAbsent(sort(c), sortOrder.size()));
    }

    static SavePlan merge(String text, List<Command> loaded, Set<Integer> skippedLines, Board edited) {
        List<Command> commands = BoardWriter.commands(edited);
        LineMerge merge = new LineMerge(loaded, commands);
        boolean byteOrderMark = !text.isEmpty() && text.charAt(0) == BYTE_ORDER_MARK;
        String body = byteOrderMark ? text.substring(1) : text;
        merge.carriageReturn = body.contains("\r\n") ? "\r" : "";
        merge.keepOrRewrite(body, skippedLines);
        merge.addWhatIsNew();
        String merged = (byteOrderMark ? String.valueOf(BYTE_ORDER_MARK) : "") + merge.join(body);
        if (loadsTo(merged, edited)) {
            return new SavePlan(merged, new SavePlan.LostLines(merge.badLines, 0, 0), commands);
        }
        return new SavePlan(BoardWriter.toText(edited),
                new SavePlan.LostLines(merge.badLines, merge.comments, merge.blankLines), commands);
    }

    private void keepOrRewrite(String body, Set<Integer> skippedLines) {
        Map<Integer, Command> commands = new HashMap<>();
        ParsedFile.parse("", body).commands().forEach(line -> commands.put(line.line().number(), line.command()));
        List<String> lines = lines(body);
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            int number = i + 1;
            Command command = commands.get(number);
            if (skippedLines.contains(number)) {
                badLines++;
            } else if (command == null) {
                if (line.strip().isEmpty()) {
                    blankLines++;
                } else {
                    comments++;
                }
                entries.add(new Entry(line, Optional.empty(), false));
            } else if (before.containsKey(command.subject()) || after.containsKey(command.subject())) {
                keepOrRewriteFact(line, command);
            } else if (command.references().stream().noneMatch(name -> changed(Subject.thing(name)))) {
                entries.add(new Entry(line, Optional.of(command), false));
            }
        }
    }

    private void keepOrRewriteFact(String line, Command command) {
        Subject subject = command.subject();
        if (!changed(subject)) {
            entries.add(new Entry(line, Optional.of(command), false));
        } else if (written.add(subject)) {
            after.getOrDefault(subject, List.of()).forEach(c -> entries.add(newLine(c)));
        }
    }

    /** Subjects of the edited board that the text has no line for, each where its sort of line is. */
    private void addWhatIsNew() {
        after.forEach((subject, commands) -> {
            if (changed(subject) && written.add(subject)) {
                for (Command command : commands) {
                    entries.add(placeFor(command), newLine(command));
                }
            }
        });
    }

    /**
     * After the last line of the same sort; else after the last line of a sort written before it, else before the
     * first of a sort written after it; else at the end. Never before the line defining a thing it names, which a
     * load would take as a line written too early (a binding of a gizmo defined further down).
     */
    private int placeFor(Command command) {
        int afterDefinitions = 0;
        for (int i = 0; i < entries.size(); i++) {
            if (entries.get(i).command().flatMap(Command::defines).filter(command.references()::contains).isPresent()) {
                afterDefinitions = i + 1;
            }
        }
        return Math.max(afterDefinitions, placeBySort(command));
    }

    private int placeBySort(Command command) {
        int rank = sortOrder.get(sort(command));
        int lastSame = -1;
        int lastEarlier = -1;
        int firstLater = -1;
        for (int i = 0; i < entries.size(); i++) {
            Integer other = entries.get(i).command().map(c -> sortOrder.get(sort(c))).orElse(null);
            if (other == null) {
                continue;
            }
            if (other == rank) {
                lastSame = i;
            } else if (other < rank) {
                lastEarlier = i;
            } else if (firstLater < 0) {
                firstLater = i;
            }
        }
        if (lastSame >= 0) {
            return lastSame + 1;
        }
        if (lastEarlier >= 0) {
            return lastEarlier + 1;
        }
        return firstLater >= 0 ? firstLater : entries.size();
    }

    private Entry newLine(Command command) {
        return new Entry(command.toLine(), Optional.of(command), true);
    }

    private boolean changed(Subject subject) {
        List<String> now = after.containsKey(subject)
                ? after.get(subject).stream().map(Command::toLine).toList() : null;
        return !Objects.equals(before.get(subject), now);
    }

    /**
     * Gizmos and absorbers are one sort: an absorber added goes after the last gizmo line, whatever its kind. A line
     * marked {@code #@} is of its command's sort (a {@code #@KeyConnect} is a key binding), as the loader reads it.
     */
    private static Class<?> sort(Command command) {
        if (command instanceof Command.Marked marked) {
            return sort(marked.command());
        }
        return command instanceof Command.AddAbsorber ? Command.AddGizmo.class : command.getClass();
    }

    /** The lines without their LF (a CR stays with its line), and no empty last line after a final LF. */
    private static List<String> lines(String body) {
        List<String> lines = new ArrayList<>(List.of(body.split("\n", -1)));
        if (!lines.isEmpty() && lines.get(lines.size() - 1).isEmpty()) {
            lines.remove(lines.size() - 1);
        }
        return lines;
    }

    /** A text that ended without a final line break still does; an empty one gets one. */
    private String join(String body) {
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < entries.size(); i++) {
            Entry entry = entries.get(i);
            out.append(entry.text());
            if (i < entries.size() - 1 || body.isEmpty() || body.endsWith("\n")) {
                out.append(entry.isNew() ? carriageReturn : "").append('\n');
            }
        }
        return out.toString();
    }

    private static boolean loadsTo(String text, Board edited) {
        LoadResult result = BoardLoader.loadSkippingBadLines("", text);
        return result.skippedLines().isEmpty()
                && BoardContents.sameDesign(result.board(), edited);
    }
}
