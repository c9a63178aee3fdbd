package gizmoball.model;

import gizmoball.model.game.Game;
import gizmoball.model.loop.GuardCounts;
import gizmoball.model.loop.LoopSettings;
import gizmoball.model.loop.TickEvents;
import gizmoball.model.loop.TickReport;
import gizmoball.model.loop.TickRun;

/**
 * One tick of play around the loop (docs/design.md, "The tick"): the delayed actions due first, then the loop,
 * then what waits for the tick's end (hit drop targets, gates, spawns, sunk balls, plunger pulls), the clock, the
 * game, and the redraw, whose cost the next tick's report states. It keeps the guards' counts, and the last tick's
 * report once asked for: play reads the tick's events in place and makes no report (docs/design.md, "What a tick
 * allocates").
 */
final class TickCycle {
    private final Play play;
    private final EndOfTick endOfTick;
    private final DelayedActions delayed;
    private final Clock clock;
    private final Game game;
    private final BoardLoop loop;
    /** The loop, kept with its books from tick to tick. */
    private final TickRun tickRun;
    /** The last tick's report, null until it is asked for. */
    private TickReport lastTick = TickReport.NONE;
    private GuardCounts guardsFired = GuardCounts.NONE;

    TickCycle(Play play, EndOfTick endOfTick, DelayedActions delayed, Clock clock, Game game, BoardLoop loop,
              LoopSettings settings) {
        this.play = play;
        this.endOfTick = endOfTick;
        this.delayed = delayed;
        this.clock = clock;
        this.game = game;
        this.loop = loop;
        this.tickRun = new TickRun(loop, loop, settings);
    }

    /** Runs a tick of {@code dt} seconds (finite, not negative: the board checks), then {@code redraw}. */
    void run(double dt, Runnable redraw) {
        delayed.performDue(clock.time(), play);
        endOfTick.ticking(true);
        tickRun.run(dt);
        lastTick = null;   // this tick's, made when asked for
        TickEvents events = tickRun.events();
        endOfTick.dropHitTargets(events);
        endOfTick.ticking(false);
        endOfTick.removeSunk();
        play.holdPulls(dt);
        clock.tickDone();
        game.afterTick(clock.ticks(), events);
        guardsFired = guardsFired.plus(tickRun.guards());
        if (loop.timesStages()) {
            long start = System.nanoTime();
            redraw.run();
            loop.setLastRedrawNanos(System.nanoTime() - start);
        } else {
            redraw.run();
            loop.setLastRedrawNanos(0);
        }
    }

    TickReport lastTick() {
        if (lastTick == null) {
            lastTick = tickRun.report();
        }
        return lastTick;
    }

    GuardCounts guardsFired() {
        return guardsFired;
    }
}
