package gizmoball.lab;

import java.util.List;
import java.util.Map;

/**
 * What one game of the lab came to.
 *
 * @param score       the game's score
 * @param seconds     game time played, to game over or the cap
 * @param over        false if the cap ended it
 * @param ballSeconds each ball's time in play, from leaving its absorber to its drain, or to the cap
 * @param hits        per gizmo, in board order, the balls that struck it (real impacts) or that it took in
 * @param losses      every ball lost, in order
 * @param jams        every time a ball lay still outside an absorber for {@link GameTally#JAM_SECONDS}
 */
record GameResult(long score, double seconds, boolean over, double[] ballSeconds, Map<String, Integer> hits,
                  List<Loss> losses, List<Jam> jams) {

    /** A ball lost into the drain or sink {@code place}, {@code along} L from its left (or top, if it is upright). */
    record Loss(String place, double along) {
    }

    /** A ball that lay still with its centre in the cell (x, y). */
    record Jam(int x, int y) {
    }
}
