package gizmoball.boardfile;

import gizmoball.model.Board;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

/**
 * A board file's text as its author wrote it, with the board it loaded to, so that saving an edited board keeps
 * what the author wrote (comments, blank lines, order, spelling) and changes only the lines of what the edits
 * changed (see {@link LineMerge}). Made by a load ({@link LoadResult#authored()}) and by each save
 * ({@link SavePlan#saved()}).
 */
public final class AuthoredText {
    private final String text;
    /** The canonical commands of the board the text loaded to, taken when it loaded (that board may change). */
    private final List<Command> loaded;
    /** The numbers of the lines the load left out. */
    private final Set<Integer> skippedLines;

    AuthoredText(String text, Board loaded, List<BoardFileError> skipped) {
        this(text, BoardWriter.commands(loaded), skipped.stream().map(BoardFileError::line).collect(Collectors.toSet()));
    }

    private AuthoredText(String text, List<Command> loaded, Set<Integer> skippedLines) {
        this.text = text;
        this.loaded = List.copyOf(loaded);
        this.skippedLines = Set.copyOf(skippedLines);
    }

    /** The text as read or last written. */
    public String text() {
        return text;
    }

    /**
     * What saving {@code edited} writes: this text with the lines of what changed rewritten, and which of its
     * lines that would remove besides the lines of what was edited away.
     */
    public SavePlan saving(Board edited) {
        return LineMerge.merge(text, loaded, skippedLines, edited);
    }

    /** The text of a save, which the next save starts from. */
    static AuthoredText written(String text, List<Command> board) {
        return new AuthoredText(text, board, Set.of());
    }
}
