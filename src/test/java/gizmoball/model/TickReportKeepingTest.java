package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.TickReport;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * Play reads a tick's events in place, in columns reused from tick to tick, and the board makes the tick's report only
 * when asked (docs/design.md, "What a tick allocates"): a report is the asker's to keep, whenever it is asked for.
 */
class TickReportKeepingTest {
    private static final int KEY = 32;

    /**
     * 100 balls at up to 40 L/s in a box, no gravity or friction, among bumpers, a flipper swung by a key every few
     * ticks: ticks of many hits (more than the columns first hold) and of events recorded between ticks.
     */
    private static Board busyBoard() {
        Board board = new Board();
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addGizmo(GizmoKind.CIRCLE, "C1", 5, 5);
        board.addGizmo(GizmoKind.SQUARE, "S1", 14, 5);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 9, 17);
        board.bindKey(KEY, KeyEdge.DOWN, "F");
        board.bindKey(KEY, KeyEdge.UP, "F");
        SplittableRandom random = new SplittableRandom(39);
        for (int i = 0; i < 100; i++) {
            board.addBall("B" + i, 0.5 + (i % 20) * 0.95, 7.5 + (i / 20) * 1.8, random.nextDouble(-40, 40),
                    random.nextDouble(-40, 40));
        }
        return board;
    }

    private static void tick(Board board, int t) {
        if (t % 7 == 3) {
            board.keyDown(KEY);
        } else if (t % 7 == 5) {
            board.keyUp(KEY);
        }
        board.tick(Board.DEFAULT_TICK);
    }

    @Test
    void aReportKeptFromAnEarlierTickStillSaysWhatThatTickDid() {
        Board board = busyBoard();
        List<TickReport> kept = new ArrayList<>();
        List<List<PlayEvent>> seenThen = new ArrayList<>();
        for (int t = 0; t < 120; t++) {
            tick(board, t);
            if (t % 3 == 2) {
                TickReport report = board.lastTick();
                kept.add(report);
                seenThen.add(List.copyOf(report.events()));
            }
        }
        assertThat(kept.stream().mapToInt(r -> r.events().size()).max().orElse(0)).isGreaterThan(16);
        for (int i = 0; i < kept.size(); i++) {
            assertThat(kept.get(i).events()).isEqualTo(seenThen.get(i));
        }
    }

    /** A window asks at every tick; a test or the lab may ask now and then: the same reports, the same game. */
    @Test
    void aReportAskedForLateIsTheOneAskedForAtOnce() {
        Board everyTick = busyBoard();
        Board now = busyBoard();
        List<TickReport> atOnce = new ArrayList<>();
        everyTick.addObserver((b, change) -> {
            if (change == BoardChange.TICK) {
                atOnce.add(b.lastTick());
            }
        });
        int compared = 0;
        for (int t = 0; t < 150; t++) {
            tick(everyTick, t);
            tick(now, t);
            if (t % 5 == 4) {
                assertThat(now.lastTick()).isEqualTo(atOnce.get(t));
                compared += now.lastTick().events().isEmpty() ? 0 : 1;
            }
        }
        assertThat(compared).isGreaterThan(20);
        assertThat(now.game().score()).isPositive().isEqualTo(everyTick.game().score());
        assertThat(now.lastTick().events()).anyMatch(e -> e instanceof PlayEvent.Hit);
    }

    /** A key pressed after a tick swings the flipper in the next one: its event is the next tick's, however late asked. */
    @Test
    void anEventBetweenTicksIsTheNextTicksAlthoughTheLastReportIsAskedForAfterIt() {
        Board board = busyBoard();
        board.tick(Board.DEFAULT_TICK);
        board.keyDown(KEY);
        assertThat(board.lastTick().events()).noneMatch(e -> e instanceof PlayEvent.Swing);
        board.tick(Board.DEFAULT_TICK);
        assertThat(board.lastTick().events()).contains(new PlayEvent.Swing("F", true));
    }
}
