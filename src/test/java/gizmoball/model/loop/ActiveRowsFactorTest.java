package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.SplittableRandom;

import org.junit.jupiter.api.RepeatedTest;
import org.junit.jupiter.api.RepetitionInfo;
import org.junit.jupiter.api.Test;

/**
 * The active set's factor of {@link NormalImpulses}: the impulses it gives make every row of the set close by exactly
 * what it asks, checked on the rows' own coupling matrix written out here (entries of J J^T from the rows' normals),
 * as the set grows and after rows leave; and a row that depends on the set is refused.
 */
class ActiveRowsFactorTest {
    /** Residual allowed, relative to the right-hand side: the systems drawn here are well conditioned. */
    private static final double EXACT = 1e-9;

    /** Contact rows on point masses: {@code a} the ball the normal points into, {@code b} the other or -1. */
    private record Rows(int[] a, int[] b, double[] nx, double[] ny) {
        /** J_i . J_j written from the Jacobian: +n on ball a, -n on ball b. */
        double coupling(int i, int j) {
            double dot = nx[i] * nx[j] + ny[i] * ny[j];
            return dot * (same(a[i], a[j]) - same(a[i], b[j]) - same(b[i], a[j]) + same(b[i], b[j]));
        }

        private static int same(int p, int q) {
            return p >= 0 && p == q ? 1 : 0;
        }

        static Rows random(SplittableRandom random, int balls, int count) {
            int[] a = new int[count];
            int[] b = new int[count];
            double[] nx = new double[count];
            double[] ny = new double[count];
            for (int i = 0; i < count; i++) {
                a[i] = random.nextInt(balls);
                b[i] = random.nextInt(3) == 0 ? -1 : (a[i] + 1 + random.nextInt(balls - 1)) % balls;
                double angle = random.nextDouble(2 * Math.PI);
                nx[i] = Math.cos(angle);
                ny[i] = Math.sin(angle);
            }
            return new Rows(a, b, nx, ny);
        }
    }

    /** Checks that the impulses of the rows in {@code set} close each by {@code base}, and the others have none. */
    private static void assertSolves(Rows rows, boolean[] set, double[] base, double[] impulses) {
        for (int i = 0; i < set.length; i++) {
            if (!set[i]) {
                assertThat(impulses[i]).isZero();
                continue;
            }
            double closed = 0;
            for (int j = 0; j < set.length; j++) {
                closed += rows.coupling(i, j) * impulses[j];
            }
            assertThat(closed).as("row %d", i).isCloseTo(base[i], within(EXACT * (1 + Math.abs(base[i]))));
        }
    }

    /** Random rows on 2 to 13 balls, up to two a ball, and what each is to close by. */
    private record Problem(Rows rows, int count, double[] base) {
        static Problem random(SplittableRandom random) {
            int balls = 2 + random.nextInt(12);
            int count = 1 + random.nextInt(2 * balls);
            Rows rows = Rows.random(random, balls, count);
            return new Problem(rows, count, random.doubles(count, -50, 50).toArray());
        }
    }

    @RepeatedTest(200)
    void theImpulsesCloseEveryRowOfTheSetByWhatItAsks(RepetitionInfo repetition) {
        SplittableRandom random = new SplittableRandom(repetition.getCurrentRepetition());
        Problem problem = Problem.random(random);
        Rows rows = problem.rows();
        int count = problem.count();
        double[] base = problem.base();
        ActiveRowsFactor factor = new ActiveRowsFactor(count, rows::coupling);
        boolean[] set = new boolean[count];
        double[] impulses = new double[count];
        for (int i = 0; i < count; i++) {
            if (factor.add(i)) {
                set[i] = true;
                factor.solve(base, impulses);
                assertSolves(rows, set, base, impulses);
            }
        }
        for (int i = 0; i < count; i++) {
            set[i] &= random.nextBoolean();
        }
        assertThat(factor.keepOnly(set)).isTrue();
        factor.solve(base, impulses);
        assertSolves(rows, set, base, impulses);
    }

    @RepeatedTest(200)
    void keepingTheForwardSubstitutionGivesTheSameDoublesAsSolvingAfresh(RepetitionInfo repetition) {
        SplittableRandom random = new SplittableRandom(repetition.getCurrentRepetition());
        Problem problem = Problem.random(random);
        int count = problem.count();
        double[] base = problem.base();
        ActiveRowsFactor factor = new ActiveRowsFactor(1, problem.rows()::coupling);   // grown as rows join
        boolean[] set = new boolean[count];
        double[] kept = new double[count];
        double[] afresh = new double[count];
        for (int step = 0; step < 3 * count; step++) {
            int row = random.nextInt(count);
            if (set[row]) {
                set[row] = false;   // a row leaves: the rows after it join again
                assertThat(factor.keepOnly(set)).isTrue();
            } else if (factor.add(row)) {
                set[row] = true;
            }
            if (random.nextInt(4) == 0) {
                double[] other = random.doubles(count, -50, 50).toArray();
                factor.solve(other, afresh);   // another right-hand side between (as a swap's)
            }
            factor.solveKeeping(base, kept);
            factor.solve(base, afresh);
            assertThat(kept).as("step %d", step).containsExactly(afresh);
        }
    }

    @Test
    void aRowAlongTheSameNormalAsOneInTheSetIsRefused() {
        // A face and the corner flush with it, both touched by ball 0 along one normal.
        Rows rows = new Rows(new int[] {0, 0}, new int[] {-1, -1}, new double[] {0, 0}, new double[] {1, 1});
        ActiveRowsFactor factor = new ActiveRowsFactor(2, rows::coupling);
        assertThat(factor.add(0)).isTrue();
        assertThat(factor.add(1)).isFalse();
        double[] impulses = new double[2];
        factor.solve(new double[] {3, 3}, impulses);
        assertThat(impulses).containsExactly(3, 0);
    }

    @Test
    void aRowThatCombinesRowsOfTheSetIsRefused() {
        // Ball 0 on a floor and against a wall; a third surface row on its diagonal is their sum over the root of 2.
        double d = Math.sqrt(0.5);
        Rows rows = new Rows(new int[] {0, 0, 0}, new int[] {-1, -1, -1}, new double[] {0, 1, d},
                new double[] {1, 0, d});
        ActiveRowsFactor factor = new ActiveRowsFactor(3, rows::coupling);
        assertThat(factor.add(0)).isTrue();
        assertThat(factor.add(1)).isTrue();
        assertThat(factor.add(2)).isFalse();
    }

    @Test
    void twoBallsPressedTogetherShareTheImpulse() {
        // Ball 0 pressed into ball 1 along x: one unit of impulse changes their closing speed by two.
        Rows rows = new Rows(new int[] {0}, new int[] {1}, new double[] {1}, new double[] {0});
        ActiveRowsFactor factor = new ActiveRowsFactor(1, rows::coupling);
        assertThat(factor.add(0)).isTrue();
        double[] impulses = new double[1];
        factor.solve(new double[] {4}, impulses);
        assertThat(impulses[0]).isCloseTo(2, within(1e-15));
    }
}
