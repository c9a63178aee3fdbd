package gizmoball.bench;

import gizmoball.boardfile.BoardFileException;
import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * Cost per tick of the game's default method as boards grow: gizmos 0..380 with 20 balls (380 fills
 * every cell but the top row, kept for the balls), and balls 1..100 among 100 gizmos, each with the
 * spatial index on and off. The same seed for every size, so the boards differ only in size.
 */
final class Scaling {

    static final int[] GIZMOS = {0, 50, 100, 200, 300, 380};
    static final int[] BALLS = {1, 5, 10, 20, 50, 100, 150, 200};
    static final int BALLS_WHILE_GIZMOS_GROW = 20;
    static final int GIZMOS_WHILE_BALLS_GROW = 100;
    static final int STRESS_GIZMOS = 300;
    static final long SEED = 300;

    private Scaling() {
    }

    static List<ScalingPoint> run(double seconds, int samples, long minSampleNanos) {
        List<ScalingPoint> points = new ArrayList<>();
        for (int g : GIZMOS) {
            for (boolean index : new boolean[] {true, false}) {
                points.add(point("gizmos", g, BALLS_WHILE_GIZMOS_GROW, index, seconds, samples, minSampleNanos));
            }
        }
        for (int b : BALLS) {
            for (boolean index : new boolean[] {true, false}) {
                points.add(point("balls", GIZMOS_WHILE_BALLS_GROW, b, index, seconds, samples, minSampleNanos));
            }
        }
        return points;
    }

    static ScalingPoint point(String axis, int gizmos, int balls, boolean index, double seconds, int samples,
                              long minSampleNanos) {
        Scene scene = board(gizmos, balls, seconds);
        long nanos = Runner.medianCpuNanos(scene, Method.GAME_DEFAULT, index, samples, minSampleNanos);
        return new ScalingPoint(axis, gizmos, balls, index, nanos / 1e3 / scene.ticks(Method.GAME_DEFAULT));
    }

    /**
     * The stress board the game ships (boards/stress.txt, loaded by the game's loader), with the index on
     * and off: as many gizmos as the random boards' stress size, but in the bands and shafts a person laid out.
     */
    static List<ScalingPoint> shippedStressBoard(Path file, double seconds, int samples, long minSampleNanos)
            throws IOException {
        String text = Files.readString(file);
        String name = file.getFileName().toString();
        Board probe = load(file.toString(), text);
        int gizmos = probe.gizmos().size();
        int balls = probe.balls().size();
        Scene scene = new Scene(name, seconds, () -> load(file.toString(), text), KeyScript.NONE, Optional.empty(),
                Optional.empty());
        List<ScalingPoint> points = new ArrayList<>();
        for (boolean index : new boolean[] {true, false}) {
            long nanos = Runner.medianCpuNanos(scene, Method.GAME_DEFAULT, index, samples, minSampleNanos);
            points.add(new ScalingPoint(name, gizmos, balls, index, nanos / 1e3 / scene.ticks(Method.GAME_DEFAULT)));
        }
        return points;
    }

    private static Board load(String source, String text) {
        try {
            return BoardFiles.load(source, text);
        } catch (BoardFileException e) {
            throw new IllegalStateException("the shipped stress board does not load: " + e.getMessage(), e);
        }
    }

    static Scene board(int gizmos, int balls, double seconds) {
        return new Scene(gizmos + " gizmos, " + balls + " balls", seconds,
                () -> RandomBoards.generate(SEED, gizmos, balls), KeyScript.NONE, Optional.empty(), Optional.empty());
    }
}
