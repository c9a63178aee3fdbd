package gizmoball.boardfile;

import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * Builds a new board from board-file text, command by command through the board's editing operations.
 * A command the board refuses (overlap, outside, duplicate or unknown name...) becomes an error on its line,
 * just like a syntax error; the remaining commands are still applied so that one load reports every problem.
 */
final class BoardLoader {

    private BoardLoader() {
    }

    /** A new board with every applicable command, and an error for each other line. */
    static LoadResult loadSkippingBadLines(String source, String content) {
        ParsedFile parsed = ParsedFile.parse(source, content);
        Board board = new Board();
        List<BoardFileError> errors = new ArrayList<>(parsed.errors());
        for (ParsedFile.Line line : parsed.commands()) {
            try {
                line.command().applyTo(board);
            } catch (BoardEditException refused) {
                errors.add(BoardFileError.at(source, line.line(), refused.getMessage()));
            }
        }
        errors.sort(Comparator.comparingInt(BoardFileError::line));
        return new LoadResult(board, errors);
    }

    /** A new board, only if every line of the file is good. */
    static Board load(String source, String content) throws BoardFileException {
        LoadResult result = loadSkippingBadLines(source, content);
        if (!result.skippedLines().isEmpty()) {
            throw new BoardFileException(result.skippedLines());
        }
        return result.board();
    }
}
