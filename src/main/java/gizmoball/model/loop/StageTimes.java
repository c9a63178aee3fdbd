package gizmoball.model.loop;

import java.util.AbstractMap;
import java.util.AbstractSet;
import java.util.Iterator;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.Set;

/**
 * A tick's time in each stage, in nanoseconds, as {@link TickReport#stageNanos()} gives it: a read-only map over one
 * array, every stage in its order, so that a report made every tick boxes no time until one is read (issue 39). It
 * reads, compares and hashes as an {@code EnumMap} of the same times does.
 */
final class StageTimes extends AbstractMap<Stage, Long> {
    private static final Stage[] STAGES = Stage.values();
    /** No time in any stage: every report of a tick whose stages were not timed (in play) shares it. */
    private static final StageTimes NONE = new StageTimes(new long[STAGES.length]);
    private final long[] nanos;

    private StageTimes(long[] nanos) {
        this.nanos = nanos;
    }

    /** Every stage's time in {@code times}, 0 where it has none; the map itself when it is one of these. */
    static StageTimes of(Map<Stage, Long> times) {
        if (times instanceof StageTimes kept) {
            return kept;
        }
        long[] nanos = new long[STAGES.length];
        for (Stage stage : STAGES) {
            nanos[stage.ordinal()] = times.getOrDefault(stage, 0L);
        }
        return new StageTimes(nanos);
    }

    /** The times of the stages by their ordinals (copied). */
    static StageTimes of(long[] byOrdinal) {
        for (long time : byOrdinal) {
            if (time != 0) {
                return new StageTimes(byOrdinal.clone());
            }
        }
        return NONE;
    }

    @Override
    public Long get(Object key) {
        return key instanceof Stage stage ? nanos[stage.ordinal()] : null;
    }

    @Override
    public boolean containsKey(Object key) {
        return key instanceof Stage;
    }

    @Override
    public int size() {
        return STAGES.length;
    }

    @Override
    public Set<Entry<Stage, Long>> entrySet() {
        return new AbstractSet<>() {
            @Override
            public Iterator<Entry<Stage, Long>> iterator() {
                return new Iterator<>() {
                    private int next;

                    @Override
                    public boolean hasNext() {
                        return next < STAGES.length;
                    }

                    @Override
                    public Entry<Stage, Long> next() {
                        if (!hasNext()) {
                            throw new NoSuchElementException();
                        }
                        Stage stage = STAGES[next++];
                        return new SimpleImmutableEntry<>(stage, nanos[stage.ordinal()]);
                    }
                };
            }

            @Override
            public int size() {
                return STAGES.length;
            }
        };
    }
}
