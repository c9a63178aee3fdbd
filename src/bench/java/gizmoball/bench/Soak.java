package gizmoball.bench;

import gizmoball.model.Board;
import gizmoball.model.Invariants;

import java.lang.management.ManagementFactory;

/**
 * The long run of the stability report: the dense board under the game's default method for many
 * ticks, every invariant checked after every tick. Nothing on the dense board adds energy, so the
 * energy must never rise above its start value.
 */
final class Soak {

    record Result(long ticks, double simulatedSeconds, double cpuSeconds, Probe.Tally faults, long invariantTicks,
                  String firstViolation, double maxEnergyAboveStart, double startEnergy, double endEnergy) {}

    private Soak() {
    }

    static Result run(long ticks) {
        Board board = Scenes.denseBoardOnly();
        Method method = Method.GAME_DEFAULT;
        Stepper stepper = new ModelStepper(board, method.loop(), true);
        double e0 = board.energy();
        double maxAbove = 0;
        Probe.Tally faults = new Probe.Tally();
        long invariantTicks = 0;
        String first = "";
        long start = ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime();
        for (long i = 0; i < ticks; i++) {
            board.tick(method.dt());
            Probe.check(stepper, faults);
            var violations = Invariants.violations(board);
            if (!violations.isEmpty()) {
                if (invariantTicks++ == 0) {
                    first = "tick " + (i + 1) + ": " + violations.get(0);
                }
            }
            maxAbove = Math.max(maxAbove, board.energy() - e0);
        }
        double cpu = (ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime() - start) / 1e9;
        return new Result(ticks, ticks * method.dt(), cpu, faults, invariantTicks, first, maxAbove, e0, board.energy());
    }
}
