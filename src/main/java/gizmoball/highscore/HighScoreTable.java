package gizmoball.highscore;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalInt;

/**
 * A board's top ten, best first. Ties rank by time: a score equal to one already in the table goes below it (whoever
 * reached it first keeps the place), and a score equal to the tenth does not enter a full table. Immutable.
 */
public record HighScoreTable(List<HighScore> entries) {
    public static final int SIZE = 10;
    public static final HighScoreTable EMPTY = new HighScoreTable(List.of());

    public HighScoreTable {
        entries = List.copyOf(entries);
        if (entries.size() > SIZE) {
            throw new IllegalArgumentException("a table holds " + SIZE + " entries, not " + entries.size());
        }
        for (int i = 1; i < entries.size(); i++) {
            if (entries.get(i).score() > entries.get(i - 1).score()) {
                throw new IllegalArgumentException("a table is best first: " + entries.get(i).score() + " below "
                        + entries.get(i - 1).score());
            }
        }
    }

    /** The place (0 best) a game of {@code score} would take, if it ranks at all. */
    public OptionalInt placeOf(long score) {
        int place = 0;
        while (place < entries.size() && entries.get(place).score() >= score) {
            place++;
        }
        return place < SIZE ? OptionalInt.of(place) : OptionalInt.empty();
    }

    /** The table with the entry in its place, the tenth falling off a full table; unchanged if it does not rank. */
    public HighScoreTable with(HighScore entry) {
        OptionalInt place = placeOf(entry.score());
        if (place.isEmpty()) {
            return this;
        }
        List<HighScore> ranked = new ArrayList<>(entries);
        ranked.add(place.getAsInt(), entry);
        return new HighScoreTable(ranked.subList(0, Math.min(SIZE, ranked.size())));
    }

    /** The best entry, if any. */
    public Optional<HighScore> best() {
        return entries.stream().findFirst();
    }
}
