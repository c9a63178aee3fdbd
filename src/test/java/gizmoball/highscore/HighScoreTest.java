package gizmoball.highscore;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.replay.KeyScript;
import gizmoball.replay.Replay;
import java.time.LocalDate;
import java.util.List;
import java.util.UUID;
import java.util.prefs.BackingStoreException;
import java.util.prefs.Preferences;
import java.util.stream.IntStream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Each board's top ten: ranking, ties, a table per board content, and a damaged store reported, not fatal. */
class HighScoreTest {
    private static final String BOARD = "Circle C 5 5\nBall B 1.0 1.0 0.0 0.0\n";
    private static final LocalDate DAY = LocalDate.of(2026, 12, 2);

    /** A node of its own under the tests' private preferences store (build.gradle's java.util.prefs.userRoot). */
    private final Preferences node = Preferences.userRoot().node("/gizmoball-test/highscores-" + UUID.randomUUID());
    private final HighScoreStore store = new HighScoreStore(node);

    @AfterEach
    void removeNode() throws BackingStoreException {
        node.removeNode();
    }

    private static HighScore score(String name, long score) {
        return new HighScore(name, score, DAY, new Replay(BOARD, 1.0 / 60, 10, KeyScript.NONE, score, 1));
    }

    private static HighScoreTable tableOf(long... scores) {
        HighScoreTable table = HighScoreTable.EMPTY;
        for (int i = 0; i < scores.length; i++) {
            table = table.with(score("P" + i, scores[i]));
        }
        return table;
    }

    @Test
    void entriesRankBestFirstAndOnlyTheTopTenStay() {
        HighScoreTable table = tableOf(50, 300, 10, 70, 1000, 20, 30, 40, 60, 80, 90, 5);

        assertThat(table.entries()).extracting(HighScore::score)
                .containsExactly(1000L, 300L, 90L, 80L, 70L, 60L, 50L, 40L, 30L, 20L);
        assertThat(table.placeOf(25)).hasValue(9);
        assertThat(table.placeOf(20)).as("equal to the tenth: no place").isEmpty();
        assertThat(table.placeOf(5000)).hasValue(0);
        assertThat(table.with(score("late", 1)).entries()).isEqualTo(table.entries());
        assertThat(table.best().orElseThrow().score()).isEqualTo(1000);
    }

    @Test
    void aTieGoesBelowTheScoreReachedFirst() {
        HighScoreTable table = HighScoreTable.EMPTY.with(score("first", 100)).with(score("low", 50))
                .with(score("second", 100));

        assertThat(table.entries()).extracting(HighScore::name).containsExactly("first", "second", "low");
    }

    @Test
    void aTableIsKeptWithItsReplaysAndABoardOfOtherContentHasATableOfItsOwn() {
        HighScoreTable table = tableOf(IntStream.range(0, 12).mapToLong(i -> 100L * i).toArray());

        assertThat(store.save(BOARD, table)).isEmpty();

        HighScoreStore.Loaded loaded = new HighScoreStore(node).load(BOARD);
        assertThat(loaded.problem()).isEmpty();
        assertThat(loaded.table()).isEqualTo(table);
        assertThat(store.load(BOARD + "Square S 9 9\n").table()).isEqualTo(HighScoreTable.EMPTY);
        assertThat(store.load(BOARD + "Square S 9 9\n").problem()).isEmpty();
    }

    @Test
    void aTableLargerThanOnePreferenceValueIsSplitAndReadBack() {
        String big = "# " + "x".repeat(50_000) + "\n" + BOARD;
        HighScoreTable table = HighScoreTable.EMPTY.with(new HighScore("big", 7, DAY,
                new Replay(big, 1.0 / 60, 3, KeyScript.NONE, 7, 1)));

        assertThat(store.save(big, table)).isEmpty();

        assertThat(store.load(big).table()).isEqualTo(table);
    }

    @Test
    void aDamagedTableIsReportedReadAsEmptyAndReplacedByTheNextEntry() throws BackingStoreException {
        store.save(BOARD, tableOf(10, 20));
        Preferences table = node.node(HighScoreStore.keyOf(BOARD));
        for (String damage : List.of("not base64 !", "aGVsbG8=")) {
            table.put("part0", damage);

            HighScoreStore.Loaded loaded = store.load(BOARD);

            assertThat(loaded.table()).isEqualTo(HighScoreTable.EMPTY);
            assertThat(loaded.problem()).hasValueSatisfying(p -> assertThat(p)
                    .startsWith("The high scores of this board could not be read").endsWith("starts them afresh."));
        }
        table.remove("parts");
        assertThat(store.load(BOARD).problem()).hasValueSatisfying(p -> assertThat(p).contains("no parts"));

        assertThat(store.save(BOARD, HighScoreTable.EMPTY.with(score("after", 5)))).isEmpty();
        assertThat(store.load(BOARD).table().entries()).extracting(HighScore::name).containsExactly("after");
    }
}
