package gizmoball.bench;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** The printed table and the CSV files. */
final class Report {

    private Report() {
    }

    static void printScenes(PrintStream out, List<SceneResult> rows) {
        out.println();
        out.println("Speed against accuracy (cost: median CPU time; error: mean ball position error at T against the "
                + "exact path, or against " + Method.REFERENCE.label() + " where marked ref)");
        String format = "%-20s %-23s %10s %10s %11s %5s %11s %11s %9s %6s %5s %5s %5s%n";
        out.printf(Locale.ROOT, format, "scene", "method", "ms/sim s", "us/tick", "pos err L", "vs", "E drift", "E max rise",
                "apex err", "pen", "esc", "nan", "inv");
        for (SceneResult r : rows) {
            Runner.Accuracy a = r.accuracy();
            out.printf(Locale.ROOT, format, r.scene().name(), r.method().label() + (r.reference() ? " (ref)" : ""),
                    f3(r.msPerSimSecond()), f3(r.usPerTick()), e(r.positionError()),
                    r.scene().exact().isPresent() ? "exact" : "ref", e(a.energyDrift()), e(a.maxEnergyRise()),
                    Double.isNaN(a.apexError()) ? "-" : e(a.apexError()), a.faults().penetrations, a.faults().escapes,
                    a.faults().nonFinite, a.invariantTicks() < 0 ? "-" : Long.toString(a.invariantTicks()));
        }
    }

    static void printScaling(PrintStream out, List<ScalingPoint> points) {
        out.println();
        out.println("Scaling, " + Method.GAME_DEFAULT.label() + ": microseconds of CPU per tick");
        out.printf(Locale.ROOT, "%-10s %7s %6s %12s %12s %8s%n", "axis", "gizmos", "balls", "index on", "index off", "off/on");
        for (int i = 0; i + 1 < points.size(); i += 2) {
            ScalingPoint on = points.get(i);
            ScalingPoint off = points.get(i + 1);
            out.printf(Locale.ROOT, "%-10s %7d %6d %12s %12s %8.2f%n", on.axis(), on.gizmos(), on.balls(),
                    f3(on.usPerTick()), f3(off.usPerTick()), off.usPerTick() / on.usPerTick());
        }
    }

    /**
     * The headline: per scene at the game's tick length, each loop's cost and error as ratios to the game's
     * loop; and the stress-sized board's cost per tick with and without the spatial index over the first seconds
     * of play (the steady state, once balls have settled, is {@link SteadyState}'s).
     */
    static void printHeadline(PrintStream out, List<SceneResult> rows, List<ScalingPoint> scaling, double seconds) {
        int rate = Method.GAME_DEFAULT.ticksPerSecond();
        out.println();
        out.println("Headline at 1/" + rate + " s: cost and error of each loop relative to " + Method.GAME_DEFAULT.label());
        out.printf(Locale.ROOT, "%-20s %-11s %12s %12s %10s %12s%n", "scene", "loop", "ms/sim s", "pos err L", "cost x",
                "error x");
        for (SceneResult game : rows) {
            if (game.reference() || !game.method().equals(Method.GAME_DEFAULT)) {
                continue;
            }
            for (SceneResult r : rows) {
                if (r.scene() == game.scene() && !r.reference() && r.method().ticksPerSecond() == rate) {
                    out.printf(Locale.ROOT, "%-20s %-11s %12s %12s %10.2f %12s%n", r.scene().name(), r.method().loop(),
                            f3(r.msPerSimSecond()), e(r.positionError()), r.msPerSimSecond() / game.msPerSimSecond(),
                            e(r.positionError() / game.positionError()));
                }
            }
        }
        // Scaling points come in pairs, index on then off.
        for (int i = 0; i + 1 < scaling.size(); i += 2) {
            ScalingPoint on = scaling.get(i);
            ScalingPoint off = scaling.get(i + 1);
            boolean randomStress = on.axis().equals("gizmos") && on.gizmos() == Scaling.STRESS_GIZMOS;
            boolean shipped = !on.axis().equals("gizmos") && !on.axis().equals("balls");
            if (randomStress || shipped) {
                out.printf(Locale.ROOT, "Stress-sized board, %s (%d gizmos, %d balls), first %.0f s of play from load: %s us/tick "
                                + "with the spatial index, %s us/tick without (x %.1f)%n", randomStress ? "random" : on.axis(),
                        on.gizmos(), on.balls(), seconds, f3(on.usPerTick()), f3(off.usPerTick()),
                        off.usPerTick() / on.usPerTick());
            }
        }
    }

    static void printSoak(PrintStream out, Soak.Result s) {
        out.println();
        out.printf(Locale.ROOT, "Soak: dense board, %s, %d ticks (%.0f simulated s) in %.1f s CPU%n",
                Method.GAME_DEFAULT.label(), s.ticks(), s.simulatedSeconds(), s.cpuSeconds());
        out.printf(Locale.ROOT, "  non-finite ball-ticks %d, escapes %d, penetrations > %.0e L %d (deepest %s L), "
                        + "ticks the model's Invariants flagged %d%s%n",
                s.faults().nonFinite, s.faults().escapes, Probe.TOLERANCE, s.faults().penetrations, e(s.faults().deepest),
                s.invariantTicks(), s.firstViolation().isEmpty() ? "" : " (first: " + s.firstViolation() + ")");
        out.printf(Locale.ROOT, "  energy: start %.6f, end %.6f, most above start %s%n", s.startEnergy(), s.endEnergy(),
                e(s.maxEnergyAboveStart()));
    }

    static void writeScenes(Path file, List<SceneResult> rows) throws IOException {
        List<String> lines = new ArrayList<>();
        lines.add("scene,loop,ticks_per_second,reference,duration_s,ticks,cpu_ms_per_sim_s,cpu_us_per_tick,position_error_L,"
                + "error_against,energy_drift_rel,energy_max_rise_rel,apex_error_L,penetration_ball_ticks,escape_ball_ticks,"
                + "nonfinite_ball_ticks,deepest_penetration_L,invariant_ticks");
        for (SceneResult r : rows) {
            Runner.Accuracy a = r.accuracy();
            lines.add(String.join(",", r.scene().name(), r.method().loop().name(),
                    Integer.toString(r.method().ticksPerSecond()), Boolean.toString(r.reference()),
                    num(r.scene().duration()), Long.toString(r.scene().ticks(r.method())), num(r.msPerSimSecond()),
                    num(r.usPerTick()), num(r.positionError()), r.scene().exact().isPresent() ? "exact" : "reference",
                    num(a.energyDrift()), num(a.maxEnergyRise()), Double.isNaN(a.apexError()) ? "" : num(a.apexError()),
                    Long.toString(a.faults().penetrations), Long.toString(a.faults().escapes),
                    Long.toString(a.faults().nonFinite), num(a.faults().deepest),
                    a.invariantTicks() < 0 ? "" : Long.toString(a.invariantTicks())));
        }
        Files.write(file, lines);
    }

    static void writeScaling(Path file, List<ScalingPoint> points) throws IOException {
        List<String> lines = new ArrayList<>();
        lines.add("axis,gizmos,balls,spatial_index,cpu_us_per_tick");
        for (ScalingPoint p : points) {
            lines.add(String.join(",", p.axis(), Integer.toString(p.gizmos()), Integer.toString(p.balls()),
                    Boolean.toString(p.spatialIndex()), num(p.usPerTick())));
        }
        Files.write(file, lines);
    }

    static void writeSoak(Path file, Soak.Result s) throws IOException {
        Files.write(file, List.of(
                "ticks,simulated_s,cpu_s,nonfinite_ball_ticks,escape_ball_ticks,penetration_ball_ticks,deepest_penetration_L,"
                        + "invariant_ticks,start_energy,end_energy,max_energy_above_start",
                String.join(",", Long.toString(s.ticks()), num(s.simulatedSeconds()), num(s.cpuSeconds()),
                        Long.toString(s.faults().nonFinite), Long.toString(s.faults().escapes),
                        Long.toString(s.faults().penetrations), num(s.faults().deepest), Long.toString(s.invariantTicks()),
                        num(s.startEnergy()), num(s.endEnergy()), num(s.maxEnergyAboveStart()))));
    }

    private static String f3(double v) {
        return String.format(Locale.ROOT, "%.3f", v);
    }

    private static String e(double v) {
        return String.format(Locale.ROOT, "%.2e", v);
    }

    private static String num(double v) {
        return Double.toString(v);
    }
}
