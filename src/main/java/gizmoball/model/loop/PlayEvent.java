package gizmoball.model.loop;

import gizmoball.model.gizmo.GizmoKind;

import physics.Vect;

/** Something audible or visible that happened in play, reported with the tick it happened in (for sound, flashes). */
public sealed interface PlayEvent {

    /**
     * A ball hit {@code struck}: a gizmo (of {@code kind}), the outer walls or another ball ({@code kind} null for
     * both), closing at {@code speed} L/s along the contact normal. {@code ball} is the ball that hit, (atX, atY) its
     * centre at the moment of the hit (the aim preview marks it). Play keeps a hit's parts in columns
     * ({@link TickEvents}): a record is made only for a report asked for (docs/design.md, "What a tick allocates").
     */
    record Hit(Struck struck, GizmoKind kind, double speed, String ball, double atX, double atY) implements PlayEvent {
        /**
         * L/s: the slowest impact that is a real hit, the one threshold of everything that hears hits (a hit scores,
         * a hit clicks). Slower ones are a ball settling or rolling along a surface.
         */
        public static final double REAL_IMPACT_SPEED = 1;

        /** The ball's centre at the moment of the hit. */
        public Vect at() {
            return new Vect(atX, atY);
        }

        /** A real impact, not a ball settling: it scores and it is heard. */
        public boolean isRealImpact() {
            return isRealImpact(speed);
        }

        /** Whether a hit closing at {@code speed} L/s is a real impact. */
        public static boolean isRealImpact(double speed) {
            return speed >= REAL_IMPACT_SPEED;
        }
    }

    /** An absorber captured {@code ball}, whose centre was at {@code at} when it touched the absorber. */
    record Captured(String absorber, String ball, Vect at) implements PlayEvent {
    }

    /**
     * A sink took {@code ball} out of play, its centre at {@code at} when it touched the sink; the board removes it
     * once the tick is over.
     */
    record Sunk(String sink, String ball, Vect at) implements PlayEvent {
    }

    /**
     * {@code ball} entered the mouth of the portal {@code portal}, its centre at {@code at}, and left by the mouth of
     * its pair {@code exit}, its centre at {@code out}.
     */
    record Teleported(String portal, String exit, String ball, Vect at, Vect out) implements PlayEvent {
    }

    /** A spawner added the ball {@code ball} at its mouth. */
    record Spawned(String spawner, String ball) implements PlayEvent {
    }

    /** An absorber fired a ball. */
    record Fired(String absorber) implements PlayEvent {
    }

    /**
     * A ball the flipper could not squeeze out from between it and what the ball lay against stopped the flipper
     * short of its stop (docs/design.md, "Pinched balls"): a stall, not a guard.
     */
    record Jammed(String flipper, String ball) implements PlayEvent {
    }

    /** A flipper started swinging, {@code up} toward its active position or back down. */
    record Swing(String flipper, boolean up) implements PlayEvent {
    }
}
