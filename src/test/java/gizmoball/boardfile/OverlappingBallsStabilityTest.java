package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.fail;

import gizmoball.model.Board;
import gizmoball.model.Invariants;
import gizmoball.model.loop.BallView;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;

/**
 * Sixty balls loaded on top of each other among bumpers: each overlapping pair passes through until it separates,
 * and nothing goes wrong meanwhile or after: no NaN, no ball inside a gizmo or (once apart) inside another ball,
 * and no energy gained beyond the integration's allowance.
 */
class OverlappingBallsStabilityTest {
    private static final int BALLS = 60;
    private static final int TICKS = 2_000;
    private static final double DT = Board.DEFAULT_TICK;

    /** Six rows of ten, 0.3 L apart: every ball overlaps its neighbours along rows, columns and diagonals. */
    static String sixtyOverlappingBalls() {
        StringBuilder file = new StringBuilder(String.join("\n", "Square S1 2 12", "Square S2 9 13",
                "Circle C1 5 11", "Circle C2 14 12", "Triangle T1 17 14", "Triangle T2 0 16", "Rotate T2",
                "Square S3 11 17", "Circle C3 6 18", ""));
        for (int i = 0; i < BALLS; i++) {
            double x = 6 + 0.3 * (i % 10);
            double y = 4 + 0.3 * (i / 10);
            double vx = (i * 7 % 11) - 5;
            double vy = (i * 5 % 13) - 6;
            file.append(String.format(Locale.ROOT, "Ball B%d %s %s %s %s%n", i, x, y, vx, vy));
        }
        return file.toString();
    }

    @Test
    void sixtyOverlappingBallsLoadAndRunWithoutNaNPenetrationOrEnergyGain() throws BoardFileException {
        String text = sixtyOverlappingBalls();
        LoadResult result = BoardFiles.loadSkippingBadLines("sixty", text);
        assertThat(result.skippedLines()).isEmpty();
        Board board = BoardFiles.load("sixty", text);
        assertThat(board.balls()).hasSize(BALLS);
        PassingPairs passing = new PassingPairs(board);
        assertThat(result.notes()).as("one note per overlapping pair").hasSize(passing.pairs().size());
        assertThat(passing.pairs().size()).as("rows, columns and diagonals of a 10x6 grid")
                .isEqualTo(6 * 9 + 5 * 10 + 2 * 5 * 9);

        double start = board.energy();
        double startSpeeds = speeds(board);
        for (int tick = 1; tick <= TICKS; tick++) {
            board.tick(DT);
            passing.update(board);
            List<String> violations = Invariants.violations(board, passing.pairs());
            if (!violations.isEmpty()) {
                fail("after tick " + tick + ": " + violations);
            }
            // Each ball's energy may exceed its shadow energy, which elastic bounces keep, by about g dt |v| / 2.
            double allowance = 2 * board.gravity() * DT * (startSpeeds + speeds(board));
            assertThat(board.energy()).as("energy after tick " + tick).isLessThanOrEqualTo(start + allowance);
        }
    }

    private static double speeds(Board board) {
        return board.balls().stream().filter(b -> !b.isCaptured()).map(BallView::velocity)
                .mapToDouble(v -> v.length()).sum();
    }
}
