package gizmoball.fuzz;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import java.util.stream.LongStream;

/**
 * Issue 20's fuzz over fixed seeds: each dense board of {@link DenseBoards} played 1,500 ticks with its key script
 * breaks no rule of {@link TickChecker} at any tick and fires no guard. {@code gradle bench} (or {@code gradle fuzz})
 * plays 1,000 more boards, twice as long.
 */
class DenseBoardFuzzTest {
    static final int TICKS = 1_500;

    static LongStream seeds() {
        return LongStream.range(1, 41);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void aDenseBoardPlaysCleanly(long seed) {
        FuzzCase fuzzCase = DenseBoards.generate(seed, TICKS);

        FuzzPlay.Outcome outcome = FuzzPlay.play(fuzzCase, FuzzPlay.UNTIMED);

        assertThat(outcome.clean()).as("seed %d (%s):%n%s", seed, fuzzCase.recipe(), outcome.summary()).isTrue();
    }
}
