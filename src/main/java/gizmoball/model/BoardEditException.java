package gizmoball.model;

/** An editing operation was refused; the message says why and the board is exactly as it was before. */
public final class BoardEditException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    public BoardEditException(String message) {
        super(message);
    }
}
