package gizmoball.bench;

/**
 * One row of the speed/accuracy table: a scene stepped by a method. Cost is the median CPU time of a
 * plain run; the error measures come from one instrumented run (the loop is deterministic).
 */
record SceneResult(Scene scene, Method method, boolean reference, long cpuNanos, double positionError,
                   Runner.Accuracy accuracy) {

    /** Milliseconds of CPU per simulated second. */
    double msPerSimSecond() {
        return cpuNanos / 1e6 / scene.duration();
    }

    double usPerTick() {
        return cpuNanos / 1e3 / scene.ticks(method);
    }
}
