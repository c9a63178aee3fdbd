package gizmoball.bench;

import gizmoball.boardfile.BoardFileException;
import gizmoball.fuzz.KeyScript;
import gizmoball.fuzz.Reproduction;
import gizmoball.model.Board;

import java.io.IOException;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * The boards other sessions found slow or wrong, {@code ../shared/repro/} (issue 39: "no tick over 2 ms on the boards
 * you do not see"): each reproduction played untimed until the compilers have caught up with its paths
 * ({@link CompilerWarmUp}), then again with its key script, every tick timed by the thread's CPU clock.
 */
final class Reproductions {
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    /**
     * One file's timed play, after {@code warmPlays} untimed ones: its balls at the end, the mean and slowest tick and
     * the ticks over the fuzz's limit.
     */
    record Row(String file, int ticks, int warmPlays, int balls, double meanUs, double maxUs, int ticksOver) {
    }

    private Reproductions() {
    }

    static List<Row> run(PrintStream out, Path dir) throws IOException {
        List<Row> rows = new ArrayList<>();
        for (Path file : files(dir)) {
            rows.add(play(file));
        }
        out.println();
        out.printf(Locale.ROOT, "Reproductions (%s), each played untimed until the JIT compilers were quiet during a "
                + "play (warm: how many plays), then timed by CPU with its key script%n", dir);
        String format = "%-28s %6s %4s %5s %9s %9s %12s%n";
        out.printf(Locale.ROOT, format, "file", "ticks", "warm", "balls", "mean us", "max us", "ticks > " + Targets.ms(
                Targets.FUZZ_TICK_NANOS) + " ms");
        for (Row r : rows) {
            out.printf(Locale.ROOT, format, r.file(), r.ticks(), r.warmPlays(), r.balls(),
                    String.format(Locale.ROOT, "%.1f", r.meanUs()), String.format(Locale.ROOT, "%.1f", r.maxUs()),
                    r.ticksOver());
        }
        return rows;
    }

    static void write(Path file, List<Row> rows) throws IOException {
        List<String> lines = new ArrayList<>();
        lines.add("file,ticks,warm_plays,balls_end,cpu_mean_us,cpu_max_us,ticks_over_limit");
        for (Row r : rows) {
            lines.add(String.format(Locale.ROOT, "%s,%d,%d,%d,%.3f,%.3f,%d", r.file(), r.ticks(), r.warmPlays(),
                    r.balls(), r.meanUs(), r.maxUs(), r.ticksOver()));
        }
        Files.write(file, lines);
    }

    private static Row play(Path file) throws IOException {
        String source = file.toString();
        Reproduction reproduction = Reproduction.parse(source, Files.readString(file));
        Board untimed = load(reproduction, source);
        int warmPlays = CompilerWarmUp.play(() -> playOnce(untimed.copy(), reproduction, null));
        long[] nanos = new long[reproduction.ticks()];
        Board board = load(reproduction, source);
        playOnce(board, reproduction, nanos);
        long sum = 0;
        long max = 0;
        int over = 0;
        for (long n : nanos) {
            sum += n;
            max = Math.max(max, n);
            over += n > Targets.FUZZ_TICK_NANOS ? 1 : 0;
        }
        return new Row(String.valueOf(file.getFileName()), nanos.length, warmPlays, board.balls().size(),
                sum / 1e3 / nanos.length, max / 1e3, over);
    }

    /** Plays the reproduction's ticks with its keys; {@code nanos}, when given, gets each tick's CPU time. */
    private static void playOnce(Board board, Reproduction reproduction, long[] nanos) {
        KeyScript.Player keys = reproduction.keys().player();
        for (int t = 0; t < reproduction.ticks(); t++) {
            keys.beforeTick(board, t + 1);
            long start = nanos == null ? 0 : THREADS.getCurrentThreadCpuTime();
            board.tick(Reproduction.DT);
            if (nanos != null) {
                nanos[t] = THREADS.getCurrentThreadCpuTime() - start;
            }
        }
    }

    private static Board load(Reproduction reproduction, String source) throws IOException {
        try {
            return reproduction.load(source);
        } catch (BoardFileException e) {
            throw new IOException("cannot load " + source + ": " + e.getMessage(), e);
        }
    }

    private static List<Path> files(Path dir) throws IOException {
        try (Stream<Path> list = Files.list(dir)) {
            return list.filter(Files::isRegularFile).filter(p -> p.toString().endsWith(".txt")).sorted().toList();
        }
    }
}
