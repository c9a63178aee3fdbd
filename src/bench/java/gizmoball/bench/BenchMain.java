package gizmoball.bench;

import physics.Vect;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;

/**
 * The benchmark: every scene with every method (cost and error), the scaling runs, the soak, the aim preview and
 * the steady state of play (issue 10), the dense-board fuzz (issue 20, {@link FuzzSurvey}); a table on standard output,
 * and in the output directory the same report ({@code bench-output.txt}), its figures as Markdown tables
 * ({@code results.md}, {@link ResultsPage}), CSV and PNG charts and the fuzz's Markdown.
 * <p>
 * Arguments: {@code [--quick] [--parts P,...] --scripts DIR --boards DIR [--peers DIR] [--repro DIR] --out DIR}
 * (which parts to run, all by default: scenes, scaling, soak, preview, steady, repro, fuzz; key scripts, the game's
 * sample boards, other implementations' boards for the steady state and the guard survey, reproductions of slow or
 * wrong boards, where to write). A run of some parts only writes their tables and the targets they judge.
 * {@code --quick} takes fewer and shorter timing samples, shorter scaling runs, a shorter soak and shorter
 * steady-state windows and fewer, shorter fuzz boards, for a smoke run under two minutes.
 */
public final class BenchMain {

    /** How much work each part does. */
    record Effort(int samples, long minSampleNanos, double scalingSeconds, long soakTicks, SteadyState.Windows steady,
                  FuzzSurvey.Effort fuzz) {
        static final Effort FULL = new Effort(5, 20_000_000, 5, 1_000_000, SteadyState.Windows.FULL,
                FuzzSurvey.Effort.FULL);
        static final Effort QUICK = new Effort(3, 5_000_000, 1, 50_000, SteadyState.Windows.QUICK,
                FuzzSurvey.Effort.QUICK);
    }

    private BenchMain() {
    }

    public static void main(String[] args) throws IOException {
        Effort effort = Effort.FULL;
        Path scripts = Path.of("bench");
        Path boards = Path.of("boards");
        Path out = Path.of("build/reports/bench");
        Optional<Path> peers = Optional.empty();
        Optional<Path> repro = Optional.empty();
        Set<String> parts = new LinkedHashSet<>(PARTS);
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--quick" -> effort = Effort.QUICK;
                case "--parts" -> parts = parts(args[++i]);
                case "--repro" -> repro = Optional.of(Path.of(args[++i]));
                case "--scripts" -> scripts = Path.of(args[++i]);
                case "--boards" -> boards = Path.of(args[++i]);
                case "--out" -> out = Path.of(args[++i]);
                case "--peers" -> peers = Optional.of(Path.of(args[++i]));
                default -> throw new IllegalArgumentException("unknown argument " + args[i]
                        + "; usage: [--quick] [--parts P,...] [--scripts DIR] [--boards DIR] [--peers DIR] [--repro DIR] "
                        + "[--out DIR]");
            }
        }
        Files.createDirectories(out);
        try (OutputStream report = Files.newOutputStream(out.resolve("bench-output.txt"));
             PrintStream stdout = new PrintStream(new Tee(System.out, report), true, "UTF-8")) {
            run(stdout, effort, parts, scripts, boards, peers, repro, out);
        }
    }

    /** The parts of a run, in the order they run. */
    static final List<String> PARTS = List.of("scenes", "scaling", "soak", "preview", "steady", "repro", "fuzz");

    private static Set<String> parts(String list) {
        Set<String> parts = new LinkedHashSet<>();
        for (String part : list.split(",")) {
            if (!PARTS.contains(part.strip())) {
                throw new IllegalArgumentException("unknown part " + part + "; the parts are " + String.join(", ", PARTS));
            }
            parts.add(part.strip());
        }
        return parts;
    }

    private static void run(PrintStream stdout, Effort effort, Set<String> parts, Path scripts, Path boards,
                            Optional<Path> peers, Optional<Path> repro, Path out) throws IOException {
        long wallStart = System.nanoTime();
        ResultsPage page = new ResultsPage(effort == Effort.QUICK);
        List<Targets.Verdict> verdicts = new ArrayList<>();
        List<SceneResult> scenes = parts.contains("scenes") ? scenes(stdout, effort, scripts, out, page) : List.of();
        if (parts.contains("scaling")) {
            scaling(stdout, effort, boards, out, scenes);
        }
        if (parts.contains("soak")) {
            stdout.println("soak");
            Soak.Result soak = Soak.run(effort.soakTicks());
            Report.printSoak(stdout, soak);
            Report.writeSoak(out.resolve("soak.csv"), soak);
            page.soak(soak);
        }
        if (parts.contains("preview")) {
            stdout.println("aim preview");
            List<PreviewCost.Row> preview = PreviewCost.run(boards, effort.samples());
            PreviewCost.print(stdout, preview);
            PreviewCost.write(out.resolve("preview.csv"), preview);
            page.preview(preview);
        }
        if (parts.contains("steady")) {
            stdout.println("steady state");
            verdicts.addAll(Targets.steadyState(SteadyState.run(stdout, boards, peers, effort.steady(), out, page)));
        }
        if (parts.contains("repro")) {
            List<Reproductions.Row> rows = repro.isPresent() ? Reproductions.run(stdout, repro.get()) : List.of();
            if (repro.isEmpty()) {
                stdout.println("note: no reproductions folder (--repro DIR; gradle passes ../shared/repro when it exists)");
            }
            Reproductions.write(out.resolve("reproductions.csv"), rows);
            page.reproductions(rows);
            verdicts.addAll(Targets.reproductions(rows));
        }
        if (parts.contains("fuzz")) {
            stdout.println();
            verdicts.addAll(Targets.fuzz(FuzzSurvey.run(stdout, effort.fuzz(), out)));
        }
        Targets.print(stdout, verdicts);
        page.targets(verdicts);

        double seconds = (System.nanoTime() - wallStart) / 1e9;
        page.write(out, seconds);
        stdout.printf(Locale.ROOT, "%nwrote results.md, CSV and charts to %s in %.0f s wall time%n", out.toAbsolutePath(),
                seconds);
    }

    /** Every scene with every method: cost and error, the table and the work-precision charts; the rows. */
    private static List<SceneResult> scenes(PrintStream stdout, Effort effort, Path scripts, Path out, ResultsPage page)
            throws IOException {
        List<Scene> scenes = Scenes.all(scripts);
        stdout.println("warm-up");
        for (Scene scene : scenes) {
            for (Method method : Method.all()) {
                Runner.cpuNanos(scene, method, true);
            }
        }
        List<SceneResult> rows = new ArrayList<>();
        for (Scene scene : scenes) {
            stdout.println("scene: " + scene.name());
            rows.addAll(runScene(scene, effort));
        }
        Report.printScenes(stdout, rows);
        Report.writeScenes(out.resolve("accuracy.csv"), rows);
        page.scenes(rows);
        for (Scene scene : scenes) {
            Charts.workPrecision(out, scene, rows);
        }
        return rows;
    }

    /**
     * Cost per tick against gizmos and balls, and the shipped stress board: table, CSV and charts, and the headline
     * of the scenes' rows (none when the scenes were not run) beside the scaling.
     */
    private static void scaling(PrintStream stdout, Effort effort, Path boards, Path out, List<SceneResult> scenes)
            throws IOException {
        stdout.println("scaling runs");
        List<ScalingPoint> scaling = new ArrayList<>(Scaling.run(effort.scalingSeconds(), effort.samples(),
                effort.minSampleNanos()));
        scaling.addAll(Scaling.shippedStressBoard(boards.resolve("stress.txt"), effort.scalingSeconds(), effort.samples(),
                effort.minSampleNanos()));
        Report.printScaling(stdout, scaling);
        Report.printHeadline(stdout, scenes, scaling, effort.scalingSeconds());
        Report.writeScaling(out.resolve("scaling.csv"), scaling);
        Charts.scaling(out, scaling);
    }

    /** Standard output and the report file at once. */
    private static final class Tee extends OutputStream {
        private final OutputStream first;
        private final OutputStream second;

        Tee(OutputStream first, OutputStream second) {
            this.first = first;
            this.second = second;
        }

        @Override
        public void write(int b) throws IOException {
            first.write(b);
            second.write(b);
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            first.write(b, off, len);
            second.write(b, off, len);
        }

        @Override
        public void flush() throws IOException {
            first.flush();
            second.flush();
        }
    }

    /** The reference run (where there is no exact path), then every method: cost and accuracy. */
    private static List<SceneResult> runScene(Scene scene, Effort effort) {
        List<SceneResult> rows = new ArrayList<>();
        List<Vect> expected;
        if (scene.exact().isPresent()) {
            expected = scene.exact().get().at(scene.duration());
        } else {
            Runner.Accuracy reference = Runner.measure(scene, Method.REFERENCE);
            expected = reference.finalPositions();
            long cost = Runner.medianCpuNanos(scene, Method.REFERENCE, true, 1, 0);
            rows.add(new SceneResult(scene, Method.REFERENCE, true, cost, 0, reference));
        }
        for (Method method : Method.all()) {
            Runner.Accuracy accuracy = Runner.measure(scene, method);
            long cost = Runner.medianCpuNanos(scene, method, true, effort.samples(), effort.minSampleNanos());
            rows.add(new SceneResult(scene, method, false, cost,
                    Runner.meanDistance(accuracy.finalPositions(), expected), accuracy));
        }
        return rows;
    }
}
