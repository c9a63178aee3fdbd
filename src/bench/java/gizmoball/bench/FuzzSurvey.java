package gizmoball.bench;

import gizmoball.fuzz.DenseBoards;
import gizmoball.fuzz.FuzzCase;
import gizmoball.fuzz.FuzzPlay;
import gizmoball.fuzz.Violation;
import gizmoball.model.Board;
import gizmoball.model.loop.GuardCounts;

import java.io.IOException;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

/**
 * The dense-board fuzz of issue 20: boards of {@link DenseBoards} from consecutive seeds, each played with its key
 * script and checked after every tick by the test sources' independent checker ({@code gizmoball.fuzz}), every tick
 * timed by the thread's CPU clock. Prints a Markdown table (boards, clean boards, guards, jams, each kind of
 * violation, the slowest tick) and writes it with the failing boards' details to {@code fuzz.md}, one CSV line per
 * board to {@code fuzz.csv}, and the first failing boards as reproduction files (the form of
 * {@code ../shared/repro/}) to {@code fuzz-failures/}.
 *
 * <p>{@link #main} runs it alone: {@code [--quick] [--boards N] [--ticks T] [--seed S] [--out DIR]}.
 */
public final class FuzzSurvey {
    /** The first seed of the benchmark's boards (the fuzz test's seeds are small numbers: these are others). */
    static final long FIRST_SEED = 1_000_000;
    /** Reproduction files written, at most. */
    static final int REPRODUCTIONS = 20;
    /**
     * CPU a board may take, some 60 times what a board of 3,000 ticks takes: a board whose ticks cost tens of
     * milliseconds is stopped there, and reported as failing, so that one such board cannot hold up the run.
     */
    static final long BOARD_BUDGET_NANOS = 20_000_000_000L;
    /** Boards played at once, at most (one per core of the 2-core machines the targets are stated for). */
    static final int THREADS_USED = 2;
    /** Boards played untimed first, so that compiling the loop is not counted as a slow tick. */
    static final int WARM_UP_BOARDS = 10;

    /** How many boards, how long each, from which seed. */
    record Effort(int boards, int ticks, long firstSeed) {
        static final Effort FULL = new Effort(1_000, 3_000, FIRST_SEED);
        static final Effort QUICK = new Effort(100, 1_000, FIRST_SEED);
    }

    /**
     * One board's run: its outcome, its slowest tick by CPU and the ticks over {@link Targets#FUZZ_TICK_NANOS}; then,
     * once the board has been {@linkplain #replayed played again}, the slowest of those ticks the second time and how
     * many were over again (until then, the slowest tick under the limit).
     */
    record Played(FuzzCase fuzzCase, FuzzPlay.Outcome outcome, long slowestNanos, int slowestTick,
                  List<Integer> ticksOver, long replayedNanos, int ticksOverAgain) {
        Played withReplay(long nanos, int over) {
            return new Played(fuzzCase, outcome, slowestNanos, slowestTick, ticksOver, nanos, over);
        }
    }

    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    private FuzzSurvey() {
    }

    public static void main(String[] args) throws IOException {
        Effort effort = Effort.FULL;
        Integer boards = null;
        Integer ticks = null;
        Long seed = null;
        Path out = Path.of("build/reports/bench");
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--quick" -> effort = Effort.QUICK;
                case "--boards" -> boards = Integer.parseInt(args[++i]);
                case "--ticks" -> ticks = Integer.parseInt(args[++i]);
                case "--seed" -> seed = Long.parseLong(args[++i]);
                case "--out" -> out = Path.of(args[++i]);
                default -> throw new IllegalArgumentException("unknown argument " + args[i]
                        + "; usage: [--quick] [--boards N] [--ticks T] [--seed S] [--out DIR]");
            }
        }
        effort = new Effort(boards == null ? effort.boards() : boards, ticks == null ? effort.ticks() : ticks,
                seed == null ? effort.firstSeed() : seed);
        Targets.print(System.out, Targets.fuzz(run(System.out, effort, out)));
    }

    /**
     * The whole part: every board played and checked, the table printed and written with the details in dir; the sums
     * are returned for the targets.
     */
    static Totals run(PrintStream out, Effort effort, Path dir) throws IOException {
        out.printf(Locale.ROOT, "dense-board fuzz: %,d boards from seed %d, %,d ticks each%n", effort.boards(),
                effort.firstSeed(), effort.ticks());
        THREADS.setThreadCpuTimeEnabled(true);
        for (int i = 0; i < WARM_UP_BOARDS; i++) {
            FuzzPlay.play(DenseBoards.generate(-1 - i, 500), FuzzPlay.UNTIMED);
        }
        long wallStart = System.nanoTime();
        // Boards are independent and each tick is timed by its own thread's CPU clock: one thread per core.
        ExecutorService pool = Executors.newFixedThreadPool(Math.min(THREADS_USED, Runtime.getRuntime()
                .availableProcessors()));
        List<Future<Played>> futures = new ArrayList<>();
        for (int i = 0; i < effort.boards(); i++) {
            long seed = effort.firstSeed() + i;
            futures.add(pool.submit(() -> play(DenseBoards.generate(seed, effort.ticks()))));
        }
        pool.shutdown();
        List<Played> runs = new ArrayList<>();
        try {
            for (Future<Played> future : futures) {
                runs.add(future.get());
                if (runs.size() % 100 == 0) {
                    out.printf(Locale.ROOT, "  %d boards, %d clean, %.0f s%n", runs.size(),
                            runs.stream().filter(r -> r.outcome().clean()).count(),
                            (System.nanoTime() - wallStart) / 1e9);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("fuzz interrupted", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException("a fuzz board failed outside its ticks", e.getCause());
        }
        out.printf(Locale.ROOT, "  %d boards in %.0f s wall time%n", runs.size(), (System.nanoTime() - wallStart) / 1e9);
        runs = replayed(runs);
        Files.createDirectories(dir);
        String table = FuzzReport.table(effort, runs);
        out.println();
        out.print(table);
        Files.writeString(dir.resolve("fuzz.md"), FuzzReport.markdown(effort, runs, table));
        Files.writeString(dir.resolve("fuzz.csv"), FuzzReport.csv(runs));
        writeReproductions(dir.resolve("fuzz-failures"), runs);
        return Totals.of(runs);
    }

    /** One board: a copy of it is kept for its reproduction file, the board itself is played with every tick timed. */
    static Played play(FuzzCase fuzzCase) {
        FuzzCase asGenerated = new FuzzCase(fuzzCase.seed(), fuzzCase.board().copy(), fuzzCase.keys(),
                fuzzCase.ticks(), fuzzCase.recipe());
        long[] slowest = {0, 0, 0, 0};   // the slowest tick, its number, the CPU so far, the slowest under the limit
        List<Integer> over = new ArrayList<>();
        FuzzPlay.Outcome outcome = FuzzPlay.play(fuzzCase, (Board board, int tick) -> {
            long nanos = timedTick(board);
            if (nanos > slowest[0]) {
                slowest[0] = nanos;
                slowest[1] = tick;
            }
            if (nanos > Targets.FUZZ_TICK_NANOS) {
                over.add(tick);
            } else {
                slowest[3] = Math.max(slowest[3], nanos);
            }
            slowest[2] += nanos;
            if (slowest[2] > BOARD_BUDGET_NANOS) {
                throw new IllegalStateException(String.format(Locale.ROOT, "stopped: over the budget of %.0f s of "
                        + "CPU for one board", BOARD_BUDGET_NANOS / 1e9));
            }
        });
        return new Played(asGenerated, outcome, slowest[0], (int) slowest[1], List.copyOf(over),
                over.isEmpty() ? slowest[0] : slowest[3], over.size());
    }

    private static long timedTick(Board board) {
        long start = THREADS.getCurrentThreadCpuTime();
        board.tick(Board.DEFAULT_TICK);
        return THREADS.getCurrentThreadCpuTime() - start;
    }

    /**
     * Every board with a tick over {@link Targets#FUZZ_TICK_NANOS} played again, up to its last such tick, with
     * those ticks timed once more. Play is deterministic, so they are the same ticks doing the same work a second
     * time; a tick slow only the first time paid for the JVM (compiling the loop, or throwing away compiled code for
     * a path it had not yet seen), which a player pays once. A board stopped for its budget is not played again.
     */
    private static List<Played> replayed(List<Played> runs) throws IOException {
        ExecutorService pool = Executors.newFixedThreadPool(Math.min(THREADS_USED, Runtime.getRuntime()
                .availableProcessors()));
        List<Future<Played>> futures = new ArrayList<>();
        for (Played run : runs) {
            futures.add(run.ticksOver().isEmpty() ? CompletableFuture.completedFuture(run)
                    : run.outcome().failure().isPresent()
                    ? CompletableFuture.completedFuture(run.withReplay(run.slowestNanos(), run.ticksOver().size()))
                    : pool.submit(() -> replay(run)));
        }
        pool.shutdown();
        List<Played> replayed = new ArrayList<>();
        try {
            for (Future<Played> future : futures) {
                replayed.add(future.get());
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("fuzz interrupted", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException("a fuzz board failed when played again", e.getCause());
        }
        return replayed;
    }

    private static Played replay(Played first) {
        FuzzCase again = DenseBoards.generate(first.fuzzCase().seed(), first.fuzzCase().ticks());
        Set<Integer> watched = Set.copyOf(first.ticksOver());
        long[] slowest = {first.replayedNanos(), 0};
        FuzzPlay.play(again.board(), again.keys(), Collections.max(first.ticksOver()), (Board board, int tick) -> {
            long nanos = timedTick(board);
            if (watched.contains(tick)) {
                slowest[0] = Math.max(slowest[0], nanos);
                slowest[1] += nanos > Targets.FUZZ_TICK_NANOS ? 1 : 0;
            }
        });
        return first.withReplay(slowest[0], (int) slowest[1]);
    }

    private static void writeReproductions(Path dir, List<Played> runs) throws IOException {
        Files.createDirectories(dir);
        try (var old = Files.list(dir)) {
            for (Path file : old.toList()) {
                Files.delete(file);
            }
        }
        List<Played> failing = runs.stream().filter(r -> !r.outcome().clean()).limit(REPRODUCTIONS).toList();
        for (Played r : failing) {
            Files.writeString(dir.resolve("seed-" + r.fuzzCase().seed() + ".txt"), r.fuzzCase().reproduction().toText());
        }
    }

    /** Sums over the runs, for the table. */
    record Totals(long boards, long clean, GuardCounts guards, long guardBoards, long jams, long jamBoards,
                  long[] balls, long[] boardsWith, long energyBoards, long slowestNanos, Played slowest,
                  long ticksOver, long ticksOverAgain, long slowestReplayedNanos) {
        static Totals of(List<Played> runs) {
            int kinds = Violation.Kind.values().length;
            long[] balls = new long[kinds];
            long[] boardsWith = new long[kinds];
            GuardCounts guards = GuardCounts.NONE;
            Played slowest = null;
            long ticksOver = 0;
            long ticksOverAgain = 0;
            long slowestReplayed = 0;
            for (Played r : runs) {
                guards = guards.plus(r.outcome().guards());
                for (Violation.Kind kind : Violation.Kind.values()) {
                    int n = r.outcome().count(kind);
                    balls[kind.ordinal()] += n;
                    boardsWith[kind.ordinal()] += n > 0 ? 1 : 0;
                }
                if (slowest == null || r.slowestNanos() > slowest.slowestNanos()) {
                    slowest = r;
                }
                ticksOver += r.ticksOver().size();
                ticksOverAgain += r.ticksOverAgain();
                slowestReplayed = Math.max(slowestReplayed, r.replayedNanos());
            }
            return new Totals(runs.size(), runs.stream().filter(r -> r.outcome().clean()).count(), guards,
                    runs.stream().filter(r -> r.outcome().guards().total() > 0).count(),
                    runs.stream().mapToLong(r -> r.outcome().jams()).sum(),
                    runs.stream().filter(r -> r.outcome().jams() > 0).count(), balls, boardsWith,
                    runs.stream().filter(r -> r.outcome().energyChecked()).count(),
                    slowest == null ? 0 : slowest.slowestNanos(), slowest, ticksOver, ticksOverAgain,
                    slowestReplayed);
        }
    }
}
