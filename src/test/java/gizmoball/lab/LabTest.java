package gizmoball.lab;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicInteger;
import org.assertj.core.api.Assertions;
import org.junit.jupiter.api.Test;

/**
 * The lab's games are the same whatever the threads: the report is the same text on one thread and on two, and on
 * a second run; its sums agree with one another; progress is told and cancelling stops it.
 */
class LabTest {
    /** Every game of the lab draws chances of its own, never another game's draws shifted (they would repeat it). */
    @Test
    void eachGameDrawsItsOwnChances() {
        Set<Long> draws = new HashSet<>();
        int count = 0;
        for (PlayerKind kind : PlayerKind.values()) {
            for (int game = 0; game < 200; game++) {
                SplittableRandom random = new SplittableRandom(Lab.seed(game, kind));
                for (int draw = 0; draw < 8; draw++) {
                    draws.add(random.nextLong());
                    count++;
                }
            }
        }
        assertThat(draws).hasSize(count);
    }

    /** A small table: a drain that launches up the right side, a deflector, two flippers, bumpers and a sink. */
    static final String TABLE = """
            Absorber A 0 19 20 20
            Triangle Corner 19 0
            Rotate Corner
            LeftFlipper LF 6 16
            RightFlipper RF 10 16
            Circle C1 4 6
            Circle C2 12 5
            Square S1 8 10
            Square Far 0 0
            Ball B 19.75 19.75 0 0
            KeyConnect key 90 down LF
            KeyConnect key 90 up LF
            KeyConnect key 47 down RF
            KeyConnect key 47 up RF
            KeyConnect key 32 down A
            #@Sink K 15 12
            #@Balls 2
            #@Drain A
            """;
    private static final int GAMES = 6;

    static Board table() throws Exception {
        return BoardFiles.load("table", TABLE);
    }

    private static LabSettings settings(int threads) {
        return new LabSettings(GAMES, threads, 120, Board.DEFAULT_TICK);
    }

    @Test
    void theReportIsTheSameOnOneThreadAndOnTwoAndOnASecondRun() throws Exception {
        String one = Lab.run(table(), "table", settings(1), LabProgress.NONE).report().toJson();
        String two = Lab.run(table(), "table", settings(2), LabProgress.NONE).report().toJson();
        String again = Lab.run(table(), "table", settings(2), LabProgress.NONE).report().toJson();
        assertThat(two).isEqualTo(one);
        assertThat(again).isEqualTo(one);
    }

    @Test
    void theSumsAgree() throws Exception {
        LabResult result = Lab.run(table(), "table", settings(2), LabProgress.NONE);
        for (PlayerReport player : List.of(result.report().autoplayer(), result.report().idle())) {
            assertThat(player.games()).isEqualTo(GAMES);
            assertThat(player.scores().stream().mapToInt(PlayerReport.ScoreCount::games).sum()).isEqualTo(GAMES);
            assertThat(player.distinctScores()).isEqualTo(player.scores().size());
            assertThat(player.score().min()).isLessThanOrEqualTo(player.score().mean());
            assertThat(player.score().mean()).isLessThanOrEqualTo(player.score().max());
            // Every gizmo is counted, the drain and the sink are the places balls are lost, each where along it.
            assertThat(player.hits().keySet()).containsExactly("A", "Corner", "LF", "RF", "C1", "C2", "S1", "Far",
                    "K");
            assertThat(player.neverHit()).allMatch(gizmo -> player.hits().get(gizmo) == 0);
            assertThat(player.drains()).extracting(PlayerReport.DrainReport::place).containsExactly("A", "K");
            for (PlayerReport.DrainReport drain : player.drains()) {
                assertThat(drain.along()).hasSize(drain.place().equals("A") ? 20 : 1);
                assertThat(drain.along().stream().mapToInt(Integer::intValue).sum()).isEqualTo(drain.balls());
            }
            // A game that is over lost both its balls; a capped one fewer.
            int lost = player.drains().stream().mapToInt(PlayerReport.DrainReport::balls).sum();
            int over = player.games() - player.gamesAtCap();
            assertThat(lost).isBetween(2 * over, 2 * over + player.gamesAtCap());
            assertThat(player.balls()).isGreaterThanOrEqualTo(lost);
        }
        assertThat(result.report().gamesPerPlayer()).isEqualTo(GAMES);
    }

    @Test
    void tellsItsProgressGameByGame() throws Exception {
        List<Integer> told = new ArrayList<>();
        AtomicInteger totals = new AtomicInteger();
        Lab.run(table(), "table", settings(2), (done, total) -> {
            synchronized (told) {
                told.add(done);
            }
            totals.set(total);
        });
        assertThat(totals.get()).isEqualTo(2 * GAMES);
        assertThat(told).containsExactlyInAnyOrder(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12);
    }

    @Test
    void stopsWhenCancelled() throws Exception {
        AtomicInteger asked = new AtomicInteger();
        LabProgress cancelAfterAWhile = new LabProgress() {
            @Override
            public void gamesDone(int done, int total) {
            }

            @Override
            public boolean cancelled() {
                return asked.incrementAndGet() > 100;
            }
        };
        Assertions.assertThatThrownBy(() -> Lab.run(table(), "table", settings(2), cancelAfterAWhile))
                .isInstanceOf(CancellationException.class);
    }
}
