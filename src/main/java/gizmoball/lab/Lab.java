package gizmoball.lab;

import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.BallTaking;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Plays a board many times with each {@link PlayerKind}, on several threads, and sums up the games. Each game has
 * its own copy of the board and a seed from its number and player, and the sums are taken in the games' order, so
 * the report is the same to the last bit whatever the number of threads and whichever game ends first.
 */
public final class Lab {
    private Lab() {
    }

    /**
     * Plays {@code board} (copied first: the caller may go on with it once this returns or throws) and reports on it
     * under the name {@code boardName}.
     *
     * @throws CancellationException when {@code progress} says to stop or the calling thread is interrupted
     */
    public static LabResult run(Board board, String boardName, LabSettings settings, LabProgress progress) {
        Board prototype = board.copy();
        Map<String, Integer> drainLengths = drainLengths(prototype);
        AtomicBoolean stop = new AtomicBoolean();
        LabProgress watched = new LabProgress() {
            @Override
            public void gamesDone(int done, int total) {
                progress.gamesDone(done, total);
            }

            @Override
            public boolean cancelled() {
                return stop.get() || progress.cancelled();
            }
        };
        int total = settings.games() * PlayerKind.values().length;
        AtomicInteger done = new AtomicInteger();
        Map<PlayerKind, HeatGrid> heat = new EnumMap<>(PlayerKind.class);
        Map<PlayerKind, List<Future<GameResult>>> futures = new EnumMap<>(PlayerKind.class);
        for (PlayerKind kind : PlayerKind.values()) {
            heat.put(kind, new HeatGrid());
            futures.put(kind, new ArrayList<>());
        }
        ExecutorService threads = Executors.newFixedThreadPool(Math.min(settings.threads(), total), task -> {
            Thread thread = new Thread(task, "lab");
            thread.setDaemon(true);
            return thread;
        });
        try {
            for (int game = 0; game < settings.games(); game++) {
                for (PlayerKind kind : PlayerKind.values()) {
                    long seed = seed(game, kind);
                    futures.get(kind).add(threads.submit(() -> {
                        Board own;
                        synchronized (prototype) {
                            own = prototype.copy();
                        }
                        HeatGrid gameHeat = new HeatGrid();
                        GameResult result = LabGame.play(own, kind, seed, settings, watched, gameHeat);
                        heat.get(kind).addAll(gameHeat);
                        watched.gamesDone(done.incrementAndGet(), total);
                        return result;
                    }));
                }
            }
            Map<PlayerKind, PlayerReport> reports = new EnumMap<>(PlayerKind.class);
            for (PlayerKind kind : PlayerKind.values()) {
                List<GameResult> results = new ArrayList<>();
                for (Future<GameResult> future : futures.get(kind)) {
                    results.add(future.get());
                }
                reports.put(kind, PlayerReport.of(results, drainLengths));
            }
            return new LabResult(LabReport.of(boardName, settings, reports.get(PlayerKind.AUTOPLAYER),
                    reports.get(PlayerKind.IDLE)), heat.get(PlayerKind.AUTOPLAYER));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new CancellationException("the lab was interrupted");
        } catch (ExecutionException e) {
            if (e.getCause() instanceof CancellationException cancelled) {
                throw cancelled;
            }
            if (e.getCause() instanceof RuntimeException failure) {
                throw failure;
            }
            throw new IllegalStateException("a game of the lab failed", e.getCause());
        } finally {
            stop.set(true);
            threads.shutdownNow();
        }
    }

    /**
     * A game's seed, from its number and player: the same game gets the same chances on every run. The number and
     * player are mixed (SplitMix64's finaliser) because a {@code SplittableRandom} steps its seed by the golden gamma:
     * seeds a multiple of it apart would give each game the draws of the one before, shifted by one, so that games
     * repeat each other.
     */
    static long seed(int game, PlayerKind kind) {
        long z = 0x9E3779B97F4A7C15L * (game + 1) + 0xBF58476D1CE4E5B9L * kind.ordinal();
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /** The drains and sinks of the board, in board order, with their length in cells. */
    private static Map<String, Integer> drainLengths(Board board) {
        Map<String, Integer> lengths = new LinkedHashMap<>();
        for (Gizmo gizmo : board.gizmos()) {
            if (gizmo.kind().ballTaking() == BallTaking.REMOVES || board.gameRules().isDrain(gizmo.name())) {
                lengths.put(gizmo.name(), Math.max(gizmo.width(), gizmo.height()));
            }
        }
        return lengths;
    }
}
