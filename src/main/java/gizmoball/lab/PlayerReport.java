package gizmoball.lab;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * What one player's games of a board came to (docs/running.md, "The board lab", gives every field).
 *
 * @param games          games played
 * @param gamesAtCap     games the cap ended before game over
 * @param score          the scores' mean, spread, least and greatest
 * @param distinctScores how many different scores the games ended on
 * @param scores         each score reached, lowest first, with the number of games that ended on it
 * @param secondsPerBall each ball's time in play (leaving its absorber to its drain, or to the cap)
 * @param balls          balls that went into play
 * @param drains         balls lost by drain or sink, in board order, with where along it they went in
 * @param hits           per gizmo, in board order: balls that struck it or that it took in
 * @param neverHit       the gizmos no ball struck in any game, in board order
 * @param jams           balls that lay still outside an absorber for {@link GameTally#JAM_SECONDS} or more
 */
public record PlayerReport(int games, int gamesAtCap, Spread score, int distinctScores, List<ScoreCount> scores,
                           Spread secondsPerBall, int balls, List<DrainReport> drains, Map<String, Integer> hits,
                           List<String> neverHit, JamReport jams) {

    /** {@code games} games ended on {@code score}. */
    public record ScoreCount(long score, int games) {
    }

    /**
     * {@code balls} balls lost into the drain or sink {@code place}; {@code along[i]} of them went in between i and
     * i + 1 L from its left end (its top end, if it is taller than wide).
     */
    public record DrainReport(String place, int balls, List<Integer> along) {
    }

    /** {@code balls} jams in {@code games} games; {@code places}: the cells they lay in, most first. */
    public record JamReport(int balls, int games, List<JamPlace> places) {
    }

    /** {@code balls} balls lay jammed with their centre in the cell (x, y). */
    public record JamPlace(int x, int y, int balls) {
    }

    /** The sums of the games, taken in the order given; {@code widths} gives the drains' and sinks' lengths. */
    static PlayerReport of(List<GameResult> results, Map<String, Integer> widths) {
        double[] scores = results.stream().mapToDouble(GameResult::score).toArray();
        TreeMap<Long, Integer> byScore = new TreeMap<>();
        results.forEach(r -> byScore.merge(r.score(), 1, Integer::sum));
        List<ScoreCount> scoreCounts = new ArrayList<>();
        byScore.forEach((score, games) -> scoreCounts.add(new ScoreCount(score, games)));
        double[] ballSeconds = results.stream().flatMapToDouble(r -> Arrays.stream(r.ballSeconds())).toArray();

        Map<String, Integer> hits = new LinkedHashMap<>();
        results.forEach(r -> r.hits().forEach((gizmo, count) -> hits.merge(gizmo, count, Integer::sum)));
        List<String> neverHit = hits.entrySet().stream().filter(e -> e.getValue() == 0).map(Map.Entry::getKey).toList();

        Map<String, int[]> along = new LinkedHashMap<>();
        widths.forEach((place, width) -> along.put(place, new int[width]));
        results.forEach(r -> r.losses().forEach(loss -> {
            int[] cells = along.get(loss.place());
            cells[Math.max(0, Math.min(cells.length - 1, (int) loss.along()))]++;
        }));
        List<DrainReport> drains = new ArrayList<>();
        along.forEach((place, cells) -> drains.add(new DrainReport(place, Arrays.stream(cells).sum(),
                Arrays.stream(cells).boxed().toList())));

        return new PlayerReport(results.size(), (int) results.stream().filter(r -> !r.over()).count(),
                Spread.of(scores), byScore.size(), scoreCounts, Spread.of(ballSeconds), ballSeconds.length, drains,
                hits, neverHit, jams(results));
    }

    private static JamReport jams(List<GameResult> results) {
        Map<GameResult.Jam, Integer> byPlace = new LinkedHashMap<>();
        results.forEach(r -> r.jams().forEach(jam -> byPlace.merge(jam, 1, Integer::sum)));
        List<JamPlace> places = new ArrayList<>();
        byPlace.forEach((jam, balls) -> places.add(new JamPlace(jam.x(), jam.y(), balls)));
        places.sort((a, b) -> b.balls() != a.balls() ? Integer.compare(b.balls(), a.balls())
                : a.y() != b.y() ? Integer.compare(a.y(), b.y()) : Integer.compare(a.x(), b.x()));
        int balls = places.stream().mapToInt(JamPlace::balls).sum();
        return new JamReport(balls, (int) results.stream().filter(r -> !r.jams().isEmpty()).count(), places);
    }
}
