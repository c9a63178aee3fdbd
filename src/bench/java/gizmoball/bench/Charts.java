package gizmoball.bench;

import org.knowm.xchart.AnnotationLine;
import org.knowm.xchart.AnnotationText;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;

/** The PNG charts: one work-precision chart per scene, the two scaling charts and the steady-state chart. */
final class Charts {

    /** Log axes cannot show an exact zero; errors below this are drawn at this floor. */
    static final double ERROR_FLOOR = 1e-15;

    private static final org.knowm.xchart.style.markers.Marker[] MARKERS =
            {SeriesMarkers.SQUARE, SeriesMarkers.CIRCLE, SeriesMarkers.TRIANGLE_UP};

    private Charts() {
    }

    static void workPrecision(Path dir, Scene scene, List<SceneResult> rows) throws IOException {
        XYChart chart = new XYChartBuilder().width(800).height(560)
                .title("Work-precision: " + scene.name() + " (T = " + fmt(scene.duration()) + " s; points labelled with the tick, s)")
                .xAxisTitle("CPU ms per simulated second (log)")
                .yAxisTitle("position error at T, L (log" + (scene.exact().isPresent() ? ", vs exact" : ", vs reference") + ")")
                .build();
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideSW);
        for (Loop loop : Loop.values()) {
            List<SceneResult> line = rows.stream()
                    .filter(r -> r.scene() == scene && !r.reference() && r.method().loop() == loop)
                    .sorted((a, b) -> Integer.compare(a.method().ticksPerSecond(), b.method().ticksPerSecond()))
                    .collect(Collectors.toList());
            if (line.isEmpty()) {
                continue;
            }
            double[] x = line.stream().mapToDouble(SceneResult::msPerSimSecond).toArray();
            double[] y = line.stream().mapToDouble(r -> Math.max(ERROR_FLOOR, r.positionError())).toArray();
            XYSeries series = chart.addSeries(loop.toString(), x, y);
            series.setMarker(MARKERS[loop.ordinal()]);
            for (int i = 0; i < line.size(); i++) {
                // Tick length next to each point, a little above it on the log scale.
                chart.addAnnotation(new AnnotationText("1/" + line.get(i).method().ticksPerSecond(), x[i], y[i] * 1.25, false));
            }
        }
        save(chart, dir.resolve("work-precision-" + scene.name().replace(' ', '-') + ".png"));
    }

    static void scaling(Path dir, List<ScalingPoint> points) throws IOException {
        scalingChart(dir, points, "gizmos", "number of gizmos (" + Scaling.BALLS_WHILE_GIZMOS_GROW + " balls)");
        scalingChart(dir, points, "balls", "number of balls (log; " + Scaling.GIZMOS_WHILE_BALLS_GROW + " gizmos)");
    }

    private static void scalingChart(Path dir, List<ScalingPoint> points, String axis, String xTitle) throws IOException {
        XYChart chart = new XYChartBuilder().width(800).height(560)
                .title("Cost per tick against board size, " + Method.GAME_DEFAULT.label())
                .xAxisTitle(xTitle).yAxisTitle("CPU microseconds per tick (log)").build();
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideNW);
        // Costs span four decades; the ball axis also grows geometrically (the gizmo axis starts at 0).
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setXAxisLogarithmic(axis.equals("balls"));
        for (boolean index : new boolean[] {true, false}) {
            List<ScalingPoint> line = points.stream().filter(p -> p.axis().equals(axis) && p.spatialIndex() == index)
                    .collect(Collectors.toList());
            double[] x = line.stream().mapToDouble(p -> axis.equals("gizmos") ? p.gizmos() : p.balls()).toArray();
            double[] y = line.stream().mapToDouble(ScalingPoint::usPerTick).toArray();
            chart.addSeries(index ? "spatial index on" : "spatial index off (scan every gizmo)", x, y);
        }
        save(chart, dir.resolve("scaling-" + axis + ".png"));
    }

    /**
     * Cost per tick against tick number, mean and max of each bin of ticks (log), with the start of the measured
     * window and the targets of its mean and max ({@link Targets}) marked.
     */
    static void tickCost(Path dir, String board, List<SteadyState.Bin> bins, int binTicks, int windowStart)
            throws IOException {
        XYChart chart = new XYChartBuilder().width(900).height(560)
                .title("Cost per tick against tick number: " + board + " at 1/60 s (each point " + binTicks + " ticks)")
                .xAxisTitle("tick").yAxisTitle("wall microseconds per tick (log)").build();
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setYAxisDecimalPattern("#,##0");
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideNE);
        double[] x = bins.stream().mapToDouble(SteadyState.Bin::firstTick).toArray();
        chart.addSeries("max of " + binTicks + " ticks", x, bins.stream().mapToDouble(SteadyState.Bin::maxUs).toArray())
                .setMarker(SeriesMarkers.NONE);
        chart.addSeries("mean of " + binTicks + " ticks", x, bins.stream().mapToDouble(SteadyState.Bin::meanUs).toArray())
                .setMarker(SeriesMarkers.NONE);
        chart.addAnnotation(new AnnotationLine(windowStart, true, false));
        double top = bins.stream().mapToDouble(SteadyState.Bin::maxUs).max().orElse(1);
        double bottom = bins.stream().mapToDouble(SteadyState.Bin::meanUs).min().orElse(1);
        // Both target lines stay in view, however far from them the run was.
        chart.getStyler().setYAxisMin(Math.min(bottom, Targets.STRESS_MEAN_US) / 2);
        chart.getStyler().setYAxisMax(Math.max(top, Targets.STRESS_MAX_US) * 2);
        double right = x.length == 0 ? 0 : x[x.length - 1];
        chart.addAnnotation(new AnnotationText("measured from here ->", windowStart + right * 0.08, top, false));
        for (double target : new double[] {Targets.STRESS_MEAN_US, Targets.STRESS_MAX_US}) {
            chart.addAnnotation(new AnnotationLine(target, false, false));
        }
        chart.addAnnotation(new AnnotationText("target mean", right * 0.93, Targets.STRESS_MEAN_US * 1.25, false));
        chart.addAnnotation(new AnnotationText("target max", right * 0.93, Targets.STRESS_MAX_US * 1.25, false));
        save(chart, dir.resolve("steady-state-" + board.replace(".txt", "") + ".png"));
    }

    private static void save(XYChart chart, Path file) throws IOException {
        BitmapEncoder.saveBitmap(chart, file.toString(), BitmapEncoder.BitmapFormat.PNG);
    }

    private static String fmt(double v) {
        return String.format(Locale.ROOT, "%g", v).replaceAll("\\.?0+$", "");
    }
}
