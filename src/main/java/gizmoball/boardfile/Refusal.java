package gizmoball.boardfile;

/**
 * Thrown for a line that is not a well-formed command; the message is the reason. The parser, the argument words,
 * the peers' dialects and the orders all refuse with it, so it stands apart from each of them.
 */
final class Refusal extends Exception {
    private static final long serialVersionUID = 1L;

    Refusal(String reason) {
        super(reason);
    }
}
