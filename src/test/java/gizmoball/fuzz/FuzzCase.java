package gizmoball.fuzz;

import gizmoball.model.Board;

/**
 * One generated board with the keys to play on it: what {@link DenseBoards#generate} makes from a seed.
 *
 * @param recipe the generator's choices for this seed, for a reader of a report
 */
public record FuzzCase(long seed, Board board, KeyScript keys, int ticks, String recipe) {

    /** The case as a reproduction file (the board as it is now, which before play is as generated). */
    public Reproduction reproduction() {
        return Reproduction.of(board, ticks, keys);
    }
}
