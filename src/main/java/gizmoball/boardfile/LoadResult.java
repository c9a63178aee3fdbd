package gizmoball.boardfile;

import gizmoball.model.Board;
import java.util.List;

/**
 * A board loaded with its bad lines skipped.
 *
 * @param board        a new board holding every command of the file that could be applied
 * @param skippedLines exactly the lines left out, and why, in line order; empty when the file was clean
 * @param notes        how lines written in another implementation's way were understood, in line order
 * @param authored     the text as read, for a save that keeps what its author wrote
 */
public record LoadResult(Board board, List<BoardFileError> skippedLines, List<BoardFileNote> notes,
                         AuthoredText authored) {
    public LoadResult {
        skippedLines = List.copyOf(skippedLines);
        notes = List.copyOf(notes);
    }

    /** Nothing of the file made it in: the board is exactly a new, empty one (its settings included). */
    public boolean keptNothing() {
        return BoardWriter.toText(board).equals(BoardWriter.toText(new Board()));
    }
}
