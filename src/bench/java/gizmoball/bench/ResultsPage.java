package gizmoball.bench;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Locale;

/**
 * results.md: the figures of one run of the benchmark as Markdown tables, so that documents link to them instead of
 * retyping numbers that change with every run. Each part of the run adds its section as it finishes; the targets,
 * judged at the end, come first.
 */
final class ResultsPage {
    private final boolean quick;
    private final StringBuilder header = new StringBuilder();
    private final StringBuilder targets = new StringBuilder();
    private final StringBuilder page = new StringBuilder();

    /** A page headed by when the run began, how much work it does and the machine's load then. */
    ResultsPage(boolean quick) {
        this.quick = quick;
        header.append("# Benchmark results\n\n")
                .append("Written by `gradle bench").append(quick ? " -Pquick" : "").append("` (do not edit: the next run ")
                .append("rewrites it). Run of ")
                .append(DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm 'UTC'").format(Instant.now().atOffset(ZoneOffset.UTC)))
                .append(", ").append(quick ? "quick (shorter windows and fewer samples)" : "full").append(", ")
                .append(load()).append(". What each part measures and why: [README.md](README.md).\n");
    }

    /** Issue 20's targets against this run ({@link Targets}: what each asks, what was measured, met or not). */
    void targets(List<Targets.Verdict> verdicts) {
        targets.append("\n## Targets of issues 20 and 39 (benchmark figures on 2 cores)\n\n");
        if (quick) {
            targets.append("A quick run: its windows, pile and fuzz are shorter than those the targets are stated for, so "
                    + "these verdicts only preview a full run's.\n\n");
        }
        targets.append("| target | this run | verdict |\n|---|---|---|\n");
        for (Targets.Verdict v : verdicts) {
            targets.append("| ").append(v.target()).append(" | ").append(v.measured()).append(" | ").append(v.verdict())
                    .append(" |\n");
        }
    }

    /** Each scene at the game's tick length: every loop's cost and error (the other tick lengths: accuracy.csv). */
    void scenes(List<SceneResult> rows) {
        int rate = Method.GAME_DEFAULT.ticksPerSecond();
        section("Speed against accuracy: the scenes at 1/" + rate + " s");
        page.append("| scene | loop | CPU ms per simulated s | position error (L) |\n|---|---|---|---|\n");
        for (SceneResult r : rows) {
            if (!r.reference() && r.method().ticksPerSecond() == rate) {
                page.append(String.format(Locale.ROOT, "| %s | %s | %.3f | %.2e |%n", r.scene().name(),
                        r.method().loop(), r.msPerSimSecond(), r.positionError()));
            }
        }
    }

    void steadyState(List<SteadyState.Row> rows, SteadyState.Windows w) {
        section(String.format(Locale.ROOT, "Steady state: ticks %,d-%,d at 1/60 s, each tick timed alone", w.from(),
                w.to()));
        page.append("| board | ticks | warm-up plays | gizmos, balls | wall mean / p99 / max (us) "
                + "| CPU mean / p99 / max (us) | bytes per tick | collisions per tick: mean, max "
                + "| zero-time per tick: mean, max | asleep / awake at the end "
                + "| guards (wedged, pinched, cap) | GCs (ms) |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        for (SteadyState.Row r : rows) {
            page.append(String.format(Locale.ROOT, "| `%s` | %,d-%,d | %d | %d, %d | %s / %s / %s | %s / %s / %s "
                            + "| %,.0f | %.2f, %d | %.2f, %d | %d / %d | %d, %d, %d | %d (%d) |%n",
                    SteadyState.shortName(r.board()), r.from(), r.to(), r.warmPlays(), r.gizmos(), r.balls(),
                    us(r.meanUs()), us(r.p99Us()), us(r.maxUs()), us(r.cpuMeanUs()), us(r.cpuP99Us()), us(r.cpuMaxUs()),
                    r.bytesPerTick(),
                    r.meanCollisions(), r.maxCollisions(), r.meanZeroTime(), r.maxZeroTime(), r.asleep(), r.awake(),
                    r.guards().wedged(), r.guards().pinched(), r.guards().collisionCap(), r.gcPauses(), r.gcMillis()));
        }
    }

    void reproductions(List<Reproductions.Row> rows) {
        section("Reproductions: each file of `../shared/repro` with its key script, played again, each tick by CPU");
        page.append("| file | ticks | warm-up plays | balls at the end | CPU mean (us) | CPU max (us) | ticks over "
                + Targets.ms(Targets.FUZZ_TICK_NANOS) + " ms |\n|---|---|---|---|---|---|---|\n");
        for (Reproductions.Row r : rows) {
            page.append(String.format(Locale.ROOT, "| `%s` | %,d | %d | %d | %s | %s | %,d |%n", r.file(), r.ticks(),
                    r.warmPlays(), r.balls(),
                    us(r.meanUs()), us(r.maxUs()), r.ticksOver()));
        }
    }

    void pile(SteadyState.Pile p) {
        section("Sleeping pile");
        page.append(String.format(Locale.ROOT, "| balls | asleep after settling, at the end | farthest a ball moved (L) "
                        + "| pile (CPU us per tick) | no balls (CPU us per tick) | ratio |%n|---|---|---|---|---|---|%n"
                        + "| %d | %d, %d | %.1e | %.3f | %.3f | %.2f |%n", p.balls(), p.asleepAfterSettle(),
                p.asleepAtEnd(), p.moved(), p.pileUs(), p.emptyUs(), p.ratio()));
    }

    void survey(SteadyState.Survey s) {
        section(String.format(Locale.ROOT, "Guard survey: %,d ticks of each board", s.ticks()));
        page.append("| boards | boards a guard fired on | wedged | pinched | collision cap | jams (boards) | failed |\n")
                .append("|---|---|---|---|---|---|---|\n")
                .append(String.format(Locale.ROOT, "| %d | %d | %d | %d | %d | %d (%d) | %d |%n", s.boards().size(),
                        s.firing().size(), s.totals().wedged(), s.totals().pinched(), s.totals().collisionCap(),
                        s.jams(), s.jamming(), s.boards().stream().filter(b -> b.failure().isPresent()).count()));
        List<SteadyState.Surveyed> firing = s.firing();
        if (!firing.isEmpty()) {
            page.append("\n| board a guard fired on | balls | wedged | pinched | cap |\n|---|---|---|---|---|\n");
            for (SteadyState.Surveyed b : firing) {
                page.append(String.format(Locale.ROOT, "| `%s` | %d | %d | %d | %d |%n", b.board(), b.balls(),
                        b.guards().wedged(), b.guards().pinched(), b.guards().collisionCap()));
            }
        }
    }

    void soak(Soak.Result s) {
        section("Soak: the dense board, every invariant after every tick");
        page.append("| ticks | simulated s | CPU s | non-finite ball-ticks | escapes | penetrations | ticks flagged by "
                        + "Invariants | energy above start, most |\n|---|---|---|---|---|---|---|---|\n")
                .append(String.format(Locale.ROOT, "| %,d | %.0f | %.1f | %d | %d | %d | %d | %.1e |%n", s.ticks(),
                        s.simulatedSeconds(), s.cpuSeconds(), s.faults().nonFinite, s.faults().escapes,
                        s.faults().penetrations, s.invariantTicks(), s.maxEnergyAboveStart()));
    }

    void preview(List<PreviewCost.Row> rows) {
        section("Aim preview: one whole prediction of 3 s");
        page.append("| board | balls | median CPU ms | worst CPU ms | median wall ms | first slice reaches (s) |\n")
                .append("|---|---|---|---|---|---|\n");
        for (PreviewCost.Row r : rows) {
            page.append(String.format(Locale.ROOT, "| `%s` | %d | %.2f | %.2f | %.2f | %.2f |%n", r.board(), r.balls(),
                    r.medianCpuMs(), r.worstCpuMs(), r.medianWallMs(), r.firstSliceSeconds()));
        }
    }

    /** The end of the run: how long it took, the load then, and the files beside the page. */
    void write(Path dir, double wallSeconds) throws IOException {
        section("The run");
        page.append(String.format(Locale.ROOT, "%.0f s wall time; at the end, %s. Beside this page: the printed "
                + "report (`bench-output.txt`), the CSV files, the charts, the fuzz survey (`fuzz.md`) and the physics "
                + "library's timings per method (written by `gradle :physics-lib:benchmark`, which this run ran "
                + "first).%n", wallSeconds, load()));
        Files.writeString(dir.resolve("results.md"), header.toString() + targets + page);
    }

    private void section(String title) {
        page.append("\n## ").append(title).append("\n\n");
    }

    private static String load() {
        return String.format(Locale.ROOT, "load average %.2f on %d processors",
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(),
                Runtime.getRuntime().availableProcessors());
    }

    /** Microseconds: one decimal below 100, whole above, as the table reads best. */
    static String us(double v) {
        return v < 100 ? String.format(Locale.ROOT, "%.1f", v) : String.format(Locale.ROOT, "%,.0f", v);
    }
}
