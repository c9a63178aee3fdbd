package gizmoball.model.loop;

/**
 * The loop's tuning, each value with its unit in its name's comment (docs/design.md, "The tick" and
 * "Guards"). Lengths and speeds shared with the editor and the loader are {@link Tolerances}; the cluster solver's own
 * limits are components too. The board hands the loop {@link #STANDARD}; tests read the values from there.
 *
 * @param zeroTime                 s: a collision sooner than this after the previous one counts as zero-time
 * @param restTicksOfGravity       ticks: a normal approach slower than this many ticks' worth of the gravity pressing
 *                                 the ball into a surface is resting contact, not a bounce
 * @param sleepSpeed               L/s: a ball on its contacts slower than this is still
 * @param sleepTime                s: how long a ball must lie still on its contacts before it falls asleep
 * @param zeroTimeHitsBeforeWedged collisions of one ball at zero time in one tick before it is stopped (guard)
 * @param strikesOfASqueeze        strikes of one ball by one moving shape in a tick, after it came back from
 *                                 something, that squeeze it
 * @param strikesOfAPush           strikes of one ball by one moving shape in a tick, nothing in between, that are a push
 * @param squeezesBeforePinched    squeezes of one ball in one tick before it is stopped with the shape (guard)
 * @param bouncesAmongContacts     bounces among a ball's contacts within one collision: enough to turn an elastic ball
 *                                 back out of a wedge of half a degree; beyond, it comes to rest against them
 * @param pressSteps               steps that settle two pressed balls' velocities to rounding
 * @param maxCollisionsBase        collisions of one tick, plus {@code maxCollisionsPerBall} per awake ball, after which
 *                                 the tick ends (guard of last resort)
 * @param maxCollisionsPerBall     see {@code maxCollisionsBase}
 * @param maxCollisionsOfABall     collisions of one ball in one tick after which it moves no more in that tick (guard;
 *                                 it stops only that ball)
 * @param rattleCollisions         collisions of a ball in one tick, each soon after the last, that make it a rattle
 *                                 solved as a cluster
 * @param rattleTime               s: collisions of one ball this close together are a rattle
 * @param rattleReach              L: the farthest a rattling ball's cluster reaches for what it nearly touches
 * @param clusterBalls             balls in one contact cluster at most: the ones beyond are taken as surfaces moving as
 *                                 they move now where they move away, still where they press in
 * @param impactRounds             rounds of impacts of one cluster solve after which what still closes takes the impact
 *                                 inelastically: far more than a row of {@code clusterBalls} touching balls needs to
 *                                 pass an impact along and back; only balls ringing in a pocket they nearly fill go on
 *                                 longer, and their limit, with any loss at all, is rest
 * @param ringMatch                of the fastest ball's speed: rounds of impacts that start within this of where the
 *                                 round two before them started ring in place (a ball between two contacts that touch
 *                                 it on both sides, not quite opposite, drifting at a steady rate), and end there at
 *                                 the limit the cap gives a ring, the inelastic projection of where it is; the cap
 *                                 would have let it drift up to {@code impactRounds} / 2 times this further (0.4-2.3%
 *                                 of the speeds in the rings of fuzz seed 1000576 and {@code slow-200-balls.txt},
 *                                 which drift 5e-5 and 1.8e-4 of their speed every two rounds, 200-480 us a solve to
 *                                 the cap)
 * @param projectionSweeps         sweeps of projected Gauss-Seidel before the inelastic projection counts as not
 *                                 converging: it is the fallback for rows the active set cannot settle, and at 10,000
 *                                 sweeps a cluster of 30 balls cost half a second of one tick
 * @param activeSetChanges         changes of the projection's active set (each adds or drops one row) before it counts
 *                                 as not settling
 * @param leadTime                 s: a ball leaving a moving part's face is given what the surface gains on it over this
 *                                 time, so a turning flipper or spinner does not meet it again at once (a flipper
 *                                 sweeping a ball along a wall would strike it every microsecond)
 * @param slidingPart              the least part of a bounce's normal lying along a sliding ball's contacts for the
 *                                 shadow-energy correction to be made along them (less, and none is)
 * @param rotatingSearchSlices     slices of a flipper's swing over which the rotating search bounds a ball's motion: any
 *                                 value finds the same contacts, more take fewer search steps for fast balls (the API
 *                                 leaves it to the caller)
 * @param scheduleBlock            awake balls per block of the collision schedule, each block keeping its earliest
 *                                 collision so the search for the next reads a few blocks (speed only: any value finds
 *                                 the same collision)
 */
public record LoopSettings(double zeroTime, double restTicksOfGravity, double sleepSpeed, double sleepTime,
                           int zeroTimeHitsBeforeWedged, int strikesOfASqueeze, int strikesOfAPush,
                           int squeezesBeforePinched, int bouncesAmongContacts, int pressSteps, int maxCollisionsBase,
                           int maxCollisionsPerBall, int maxCollisionsOfABall, int rattleCollisions, double rattleTime,
                           double rattleReach, int clusterBalls, int impactRounds, double ringMatch,
                           int projectionSweeps, int activeSetChanges, double leadTime, double slidingPart,
                           int rotatingSearchSlices, int scheduleBlock) {

    /** The settings of every board, each default named by the component it sets. */
    public static final LoopSettings STANDARD = new LoopSettings(
            /* zeroTime */ 1e-12,
            /* restTicksOfGravity */ 2,
            /* sleepSpeed */ 1e-3,
            /* sleepTime */ 0.5,
            /* zeroTimeHitsBeforeWedged */ 32,
            /* strikesOfASqueeze */ 2,
            /* strikesOfAPush */ 3,
            /* squeezesBeforePinched */ 16,
            /* bouncesAmongContacts */ 360,
            /* pressSteps */ 64,
            /* maxCollisionsBase */ 500,
            /* maxCollisionsPerBall */ 100,
            /* maxCollisionsOfABall */ 400,
            /* rattleCollisions */ 8,
            /* rattleTime */ 1e-3,
            /* rattleReach */ 1e-3,
            /* clusterBalls */ 32,
            /* impactRounds */ 256,
            /* ringMatch */ 1e-3,
            /* projectionSweeps */ 500,
            /* activeSetChanges */ 200,
            /* leadTime */ 1e-3,
            /* slidingPart */ 1e-3,
            /* rotatingSearchSlices */ 16,
            /* scheduleBlock */ 16);

    /**
     * Whether a ball still for {@code stillTime} seconds, summed a tick of {@code dt} at a time, has lain still for
     * {@link #sleepTime}: the first tick that reaches it counts, and a sum that falls short only by its rounding (far
     * less than a thousandth of a tick) reaches it.
     */
    boolean stillLongEnough(double stillTime, double dt) {
        return stillTime >= sleepTime - dt / 1024;
    }
}
