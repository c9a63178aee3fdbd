package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

/** A report's stage times read, compare and hash as the EnumMap of the same times, every stage present, read-only. */
class StageTimesTest {
    @Test
    void stageTimesAreTheEnumMapOfTheSameTimes() {
        long[] nanos = new long[Stage.values().length];
        EnumMap<Stage, Long> expected = new EnumMap<>(Stage.class);
        for (Stage stage : Stage.values()) {
            nanos[stage.ordinal()] = 1_000L * (stage.ordinal() + 1) + 7;
            expected.put(stage, nanos[stage.ordinal()]);
        }
        Map<Stage, Long> times = StageTimes.of(nanos);
        nanos[0] = -1;   // copied: the tick's clock array goes on

        assertThat(times).isEqualTo(expected);
        assertThat(expected).isEqualTo(times);
        assertThat(times.hashCode()).isEqualTo(expected.hashCode());
        assertThat(List.copyOf(times.keySet())).containsExactly(Stage.values());
        assertThat(times.get(Stage.TRIGGERING)).isEqualTo(expected.get(Stage.TRIGGERING));
        assertThat(times.get("TRIGGERING")).isNull();
        assertThatThrownBy(() -> times.put(Stage.REDRAWING, 0L)).isInstanceOf(UnsupportedOperationException.class);
    }

    /** In play no stage is timed: each tick's report then shares one map of zeros, and a tick makes none. */
    @Test
    void untimedTicksShareOneMapOfZeros() {
        long[] untimed = new long[Stage.values().length];
        Map<Stage, Long> first = StageTimes.of(untimed);
        Map<Stage, Long> second = StageTimes.of(untimed.clone());

        assertThat(second).isSameAs(first);
        assertThat(first).hasSize(Stage.values().length).allSatisfy((stage, nanos) -> assertThat(nanos).isZero());
        untimed[Stage.REDRAWING.ordinal()] = 1;
        assertThat(StageTimes.of(untimed)).isNotSameAs(first).containsEntry(Stage.REDRAWING, 1L);
        assertThat(first).containsEntry(Stage.REDRAWING, 0L);
    }

    @Test
    void aReportFillsTheStagesItIsNotGivenWithZero() {
        TickReport report = new TickReport(0, Map.of(Stage.BALL_MOTION, 5L), 0, 0, 0, 0, 0, GuardCounts.NONE, List.of(),
                List.of());
        assertThat(report.stageNanos()).hasSize(Stage.values().length).containsEntry(Stage.BALL_MOTION, 5L)
                .containsEntry(Stage.REDRAWING, 0L);
    }
}
