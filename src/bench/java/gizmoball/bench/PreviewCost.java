package gizmoball.bench;

import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.loop.BallView;
import gizmoball.preview.Prediction;
import gizmoball.preview.Predictor;
import java.io.IOException;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * The aim preview's cost: on each sample board, for each ball, the time of one full prediction, 3 simulated
 * seconds (180 ticks), against the preview's budget of 8 ms: CPU time (what the code costs) and wall time (what
 * the event thread waits, which on a busy machine includes other processes' turns); and how far the first
 * 8 ms slice the editor draws at once reaches (later slices carry it on to 3 s).
 */
final class PreviewCost {
    record Row(String board, int balls, double medianCpuMs, double worstCpuMs, double medianWallMs,
               double firstSliceSeconds) {
    }

    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    private PreviewCost() {
    }

    static List<Row> run(Path boards, int samples) throws IOException {
        List<Path> files;
        try (Stream<Path> list = Files.list(boards)) {
            files = list.filter(p -> p.toString().endsWith(".txt")).sorted().toList();
        }
        Predictor predictor = new Predictor();
        List<Row> rows = new ArrayList<>();
        for (Path file : files) {
            Board board;
            try {
                board = BoardFiles.load(file);
            } catch (Exception e) {
                throw new IOException("cannot load " + file + ": " + e.getMessage(), e);
            }
            List<BallView> balls = board.balls();
            if (balls.isEmpty()) {
                continue;
            }
            // Warm up: the first predictions pay for class loading and compilation, not for the physics.
            for (int i = 0; i < 3; i++) {
                predictor.predict(board, balls.get(0).name(), Predictor.HORIZON_SECONDS, Board.DEFAULT_TICK, Long.MAX_VALUE);
            }
            double[] cpu = new double[samples * balls.size()];
            double[] wall = new double[cpu.length];
            double shortestSlice = Predictor.HORIZON_SECONDS;
            int k = 0;
            for (int s = 0; s < samples; s++) {
                for (BallView ball : balls) {
                    long cpuStart = THREADS.getCurrentThreadCpuTime();
                    long start = System.nanoTime();
                    predictor.predict(board, ball.name(), Predictor.HORIZON_SECONDS, Board.DEFAULT_TICK, Long.MAX_VALUE);
                    wall[k] = (System.nanoTime() - start) / 1e6;
                    cpu[k++] = (THREADS.getCurrentThreadCpuTime() - cpuStart) / 1e6;
                    Prediction slice = predictor.predict(board, ball.name(), Predictor.HORIZON_SECONDS,
                            Board.DEFAULT_TICK, Predictor.BUDGET_NANOS);
                    shortestSlice = Math.min(shortestSlice, slice.seconds());
                }
            }
            Arrays.sort(cpu);
            Arrays.sort(wall);
            rows.add(new Row(String.valueOf(file.getFileName()), balls.size(), cpu[cpu.length / 2], cpu[cpu.length - 1],
                    wall[wall.length / 2], shortestSlice));
        }
        return rows;
    }

    static void print(PrintStream out, List<Row> rows) {
        out.println();
        out.printf(Locale.ROOT, "Aim preview: time of one whole prediction, %.0f s = %d ticks (budget per slice %.0f ms)%n",
                Predictor.HORIZON_SECONDS, Math.round(Predictor.HORIZON_SECONDS / Board.DEFAULT_TICK),
                Predictor.BUDGET_NANOS / 1e6);
        String format = "%-20s %6s %14s %13s %15s %20s%n";
        out.printf(Locale.ROOT, format, "board", "balls", "median CPU ms", "worst CPU ms", "median wall ms",
                "first slice (min)");
        for (Row r : rows) {
            out.printf(Locale.ROOT, format, r.board(), r.balls(), f2(r.medianCpuMs()), f2(r.worstCpuMs()),
                    f2(r.medianWallMs()), f2(r.firstSliceSeconds()) + " s");
        }
    }

    private static String f2(double v) {
        return String.format(Locale.ROOT, "%.2f", v);
    }

    static void write(Path csv, List<Row> rows) throws IOException {
        List<String> lines = new ArrayList<>();
        lines.add("board,balls,median_cpu_ms,worst_cpu_ms,median_wall_ms,first_slice_s");
        for (Row r : rows) {
            lines.add(String.format(Locale.ROOT, "%s,%d,%.4f,%.4f,%.4f,%.4f", r.board(), r.balls(), r.medianCpuMs(),
                    r.worstCpuMs(), r.medianWallMs(), r.firstSliceSeconds()));
        }
        Files.write(csv, lines);
    }
}
