package gizmoball.boardfile;

import java.util.List;
import java.util.stream.Collectors;

/** A board file was refused; carries every bad line of the file, in line order, not only the first. */
public final class BoardFileException extends Exception {
    private static final long serialVersionUID = 1L;

    private final transient List<BoardFileError> errors;

    public BoardFileException(List<BoardFileError> errors) {
        super(errors.size() + (errors.size() == 1 ? " bad line" : " bad lines") + ":\n"
                + errors.stream().map(BoardFileError::toString).collect(Collectors.joining("\n")));
        if (errors.isEmpty()) {
            throw new IllegalArgumentException("a refused board file has at least one error");
        }
        this.errors = List.copyOf(errors);
    }

    public List<BoardFileError> errors() {
        return errors;
    }
}
