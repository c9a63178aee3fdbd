package gizmoball.bench;

import gizmoball.fuzz.FuzzPlay;
import gizmoball.fuzz.Violation;

import java.util.List;
import java.util.Locale;

/** The fuzz survey's Markdown table, its details and its CSV. */
final class FuzzReport {
    /** Failing boards described in full in fuzz.md, at most. */
    static final int DETAILED = 30;

    private FuzzReport() {
    }

    /** The one-row table of issue 20's form, with a header. */
    static String table(FuzzSurvey.Effort effort, List<FuzzSurvey.Played> runs) {
        FuzzSurvey.Totals t = FuzzSurvey.Totals.of(runs);
        StringBuilder md = new StringBuilder();
        md.append("| run | boards | clean | guards fired (wedged, pinched, cap) | jams | balls inside a gizmo "
                + "| balls inside a ball | escapes | NaN | energy gained | frozen | appeared, vanished, jumped astray "
                + "| slowest tick (CPU) "
                + "| ticks over " + Targets.ms(Targets.FUZZ_TICK_NANOS) + " ms | played again: of those, over; the slowest "
                + "tick | hovering (noted) |\n");
        md.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        md.append(String.format(Locale.ROOT, "| seeds %d-%d, %,d ticks | %,d | %,d | %,d on %d boards (%,d, %,d, %,d) "
                        + "| %,d on %d boards | %s | %s | %s | %s | %s of %d boards checked | %s | %s, %s, %s | %.2f ms%s | %,d "
                        + "| %,d; %.2f ms "
                        + "| %s |\n",
                effort.firstSeed(), effort.firstSeed() + effort.boards() - 1, effort.ticks(), t.boards(), t.clean(),
                t.guards().total(), t.guardBoards(), t.guards().wedged(), t.guards().pinched(),
                t.guards().collisionCap(), t.jams(), t.jamBoards(), count(t, Violation.Kind.INSIDE_GIZMO),
                count(t, Violation.Kind.INSIDE_BALL), count(t, Violation.Kind.ESCAPED),
                count(t, Violation.Kind.NOT_A_NUMBER), t.boardsWith()[Violation.Kind.ENERGY_GAINED.ordinal()],
                t.energyBoards(), count(t, Violation.Kind.FROZEN), count(t, Violation.Kind.APPEARED),
                count(t, Violation.Kind.VANISHED), count(t, Violation.Kind.JUMPED), t.slowestNanos() / 1e6,
                t.slowest() == null ? "" : String.format(Locale.ROOT, " (seed %d, tick %d)",
                        t.slowest().fuzzCase().seed(), t.slowest().slowestTick()), t.ticksOver(), t.ticksOverAgain(),
                t.slowestReplayedNanos() / 1e6, count(t, Violation.Kind.HOVERING)));
        return md.toString();
    }

    private static String count(FuzzSurvey.Totals t, Violation.Kind kind) {
        long balls = t.balls()[kind.ordinal()];
        return balls == 0 ? "0" : String.format(Locale.ROOT, "%,d on %d boards", balls, t.boardsWith()[kind.ordinal()]);
    }

    /** fuzz.md: what was run, the table, and the first failing boards with their first violations. */
    static String markdown(FuzzSurvey.Effort effort, List<FuzzSurvey.Played> runs, String table) {
        StringBuilder md = new StringBuilder("# Dense-board fuzz (issue 20)\n\n");
        md.append(String.format(Locale.ROOT, "%,d boards of `gizmoball.fuzz.DenseBoards` (seeds %d-%d), %,d ticks of "
                        + "1/60 s each with their key scripts, checked after every tick by `gizmoball.fuzz.TickChecker` "
                        + "(geometry of its own; tolerance 1e-6 L); every tick timed by the thread's CPU clock. Balls are "
                        + "counted once per board whatever the number of ticks; energy is checked on the boards without "
                        + "gravity, friction, flippers and absorbers. Frozen: a ball not moved over a tick though its velocity "
                        + "would move it, with nothing within its reach in the tick. A clean board has no violation and "
                        + "no guard. Hovering (such a ball near something, yet more than 1e-6 L from everything) is "
                        + "noted, not counted against a board.%n%n",
                effort.boards(), effort.firstSeed(), effort.firstSeed() + effort.boards() - 1, effort.ticks()));
        md.append(table).append('\n');
        List<FuzzSurvey.Played> failing = runs.stream().filter(r -> !r.outcome().clean()).toList();
        md.append(String.format(Locale.ROOT, "## Failing boards (%d; the first %d; reproduction files of the first %d "
                + "in `fuzz-failures/`)%n%n", failing.size(), Math.min(DETAILED, failing.size()),
                Math.min(FuzzSurvey.REPRODUCTIONS, failing.size())));
        for (FuzzSurvey.Played r : failing.subList(0, Math.min(DETAILED, failing.size()))) {
            FuzzPlay.Outcome o = r.outcome();
            md.append(String.format(Locale.ROOT, "- seed %d (%s): guards %d in %d ticks (cap in %d), jams %d%n",
                    r.fuzzCase().seed(), r.fuzzCase().recipe(), o.guards().total(), o.guardTicks(), o.capTicks(),
                    o.jams()));
            o.examples().forEach(v -> md.append("  - ").append(v).append('\n'));
            o.failure().ifPresent(f -> md.append("  - threw: ").append(f).append('\n'));
        }
        return md.toString();
    }

    /** One line per board. */
    static String csv(List<FuzzSurvey.Played> runs) {
        StringBuilder csv = new StringBuilder("seed,balls,gizmos,clean,wedged,pinched,cap,cap_ticks,jams");
        for (Violation.Kind kind : Violation.Kind.values()) {
            csv.append(',').append(kind.name().toLowerCase(Locale.ROOT));
        }
        String limit = Targets.ms(Targets.FUZZ_TICK_NANOS) + "ms";
        csv.append(",energy_checked,slowest_tick_us,slowest_tick,ticks_over_").append(limit)
                .append(",replayed_slowest_tick_us,replayed_ticks_over_").append(limit).append(",failure\n");
        for (FuzzSurvey.Played r : runs) {
            FuzzPlay.Outcome o = r.outcome();
            csv.append(String.format(Locale.ROOT, "%d,%d,%d,%b,%d,%d,%d,%d,%d", r.fuzzCase().seed(),
                    r.fuzzCase().board().balls().size(), r.fuzzCase().board().gizmos().size(), o.clean(),
                    o.guards().wedged(), o.guards().pinched(), o.guards().collisionCap(), o.capTicks(), o.jams()));
            for (Violation.Kind kind : Violation.Kind.values()) {
                csv.append(',').append(o.count(kind));
            }
            csv.append(String.format(Locale.ROOT, ",%b,%.1f,%d,%d,%.1f,%d,%s%n", o.energyChecked(),
                    r.slowestNanos() / 1e3, r.slowestTick(), r.ticksOver().size(), r.replayedNanos() / 1e3,
                    r.ticksOverAgain(), o.failure().map(f -> "\"" + f.replace("\"", "'") + "\"")
                            .orElse("")));
        }
        return csv.toString();
    }
}
