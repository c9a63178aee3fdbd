package gizmoball.fuzz;

import gizmoball.model.Board;
import gizmoball.model.loop.GuardCounts;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.TickReport;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * Plays a board with its key script at 1/60 s and runs the {@link TickChecker} after every tick (the board as loaded
 * too, as tick 0), collecting what broke, the guards the loop fired and the jams it reported.
 */
public final class FuzzPlay {
    /** Examples kept of each kind of violation. */
    static final int EXAMPLES = 3;

    /** How a run plays one tick: the tests just tick, the benchmark also times the tick. */
    @FunctionalInterface
    public interface Ticker {
        void tick(Board board, int tick);
    }

    /** One tick of {@link Reproduction#DT}, untimed. */
    public static final Ticker UNTIMED = (board, tick) -> board.tick(Reproduction.DT);

    /**
     * What a run found.
     *
     * @param balls       per kind of violation, the names of the balls it struck ("all" for energy)
     * @param examples    the first few violations of each kind, in the order found
     * @param guardTicks  ticks in which a guard fired
     * @param capTicks    ticks that hit the collision cap
     * @param failure     what a tick threw, if one did (the run stops there)
     */
    public record Outcome(int ticksPlayed, boolean energyChecked, Map<Violation.Kind, Set<String>> balls,
                          List<Violation> examples, GuardCounts guards, int guardTicks, int capTicks, long jams,
                          Optional<String> failure) {

        /** No rule broken, no guard fired, nothing thrown (what is only noted does not count). */
        public boolean clean() {
            return balls.entrySet().stream().allMatch(e -> !e.getKey().rule() || e.getValue().isEmpty())
                    && guards.total() == 0 && failure.isEmpty();
        }

        public int count(Violation.Kind kind) {
            return balls.get(kind).size();
        }

        /** One line per problem: the examples, the guards, the failure. */
        public String summary() {
            StringBuilder text = new StringBuilder();
            examples.forEach(v -> text.append(v).append('\n'));
            if (guards.total() > 0) {
                text.append("guards ").append(guards).append(" in ").append(guardTicks).append(" ticks, the collision cap in ")
                        .append(capTicks).append("\n");
            }
            failure.ifPresent(f -> text.append("threw: ").append(f).append('\n'));
            return text.toString();
        }
    }

    private FuzzPlay() {
    }

    public static Outcome play(FuzzCase fuzzCase, Ticker ticker) {
        return play(fuzzCase.board(), fuzzCase.keys(), fuzzCase.ticks(), ticker);
    }

    /** Plays {@code ticks} ticks of {@code board} (which it changes) with {@code keys}. */
    public static Outcome play(Board board, KeyScript keys, int ticks, Ticker ticker) {
        Map<Violation.Kind, Set<String>> balls = new EnumMap<>(Violation.Kind.class);
        for (Violation.Kind kind : Violation.Kind.values()) {
            balls.put(kind, new HashSet<>());
        }
        List<Violation> examples = new ArrayList<>();
        Map<Violation.Kind, Integer> examplesOf = new EnumMap<>(Violation.Kind.class);
        TickChecker checker = new TickChecker(board);
        record(checker.check(board, 0), balls, examples, examplesOf);
        KeyScript.Player player = keys.player();
        GuardCounts guards = GuardCounts.NONE;
        int guardTicks = 0;
        int capTicks = 0;
        long jams = 0;
        Optional<String> failure = Optional.empty();
        int played = 0;
        for (int tick = 1; tick <= ticks; tick++) {
            player.beforeTick(board, tick);
            record(checker.keysPressed(board, tick), balls, examples, examplesOf);
            try {
                ticker.tick(board, tick);
            } catch (RuntimeException e) {
                failure = Optional.of("tick " + tick + ": " + e);
                break;
            }
            played = tick;
            TickReport report = board.lastTick();
            guards = guards.plus(report.guards());
            guardTicks += report.guards().total() > 0 ? 1 : 0;
            capTicks += report.guards().collisionCap() > 0 ? 1 : 0;
            jams += report.events().stream().filter(PlayEvent.Jammed.class::isInstance).count();
            record(checker.check(board, tick), balls, examples, examplesOf);
        }
        return new Outcome(played, checker.checksEnergy(), balls, examples, guards, guardTicks, capTicks, jams,
                failure);
    }

    private static void record(List<Violation> found, Map<Violation.Kind, Set<String>> balls, List<Violation> examples,
                               Map<Violation.Kind, Integer> examplesOf) {
        for (Violation v : found) {
            balls.get(v.kind()).add(v.ball());
            if (examplesOf.merge(v.kind(), 1, Integer::sum) <= EXAMPLES) {
                examples.add(v);
            }
        }
    }
}
