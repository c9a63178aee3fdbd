package gizmoball.sound;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.TriggerSource;
import java.util.Optional;

/**
 * What the game sounds like: the cue for each game event. A hit clicks at a pitch of its own for each kind of
 * gizmo (walls lowest, balls highest) and as loud as the impact was fast; hits slower than
 * {@link PlayEvent.Hit#REAL_IMPACT_SPEED} (a ball settling, rolling contact; they score nothing either) make no sound.
 */
public final class Sounds {
    /** Impact speed (L/s) of the loudest click; faster hits are no louder. */
    static final double FULL_SPEED = 40;
    private static final double WALL_HZ = 220;
    private static final double BALL_HZ = 1320;
    private static final double SWISH_GAIN = 0.45;
    private static final double THUNK_GAIN = 0.9;
    private static final double LAUNCH_GAIN = 0.7;

    private Sounds() {
    }

    /** The sound of something that happened in play, if it makes one. */
    public static Optional<Cue> cueFor(PlayEvent event) {
        if (event instanceof PlayEvent.Hit hit) {
            if (hit.kind() != null) {
                return gizmoHit(hit.kind(), hit.speed());
            }
            return hit.struck() instanceof TriggerSource.OuterWalls ? wallHit(hit.speed()) : ballHit(hit.speed());
        }
        if (event instanceof PlayEvent.Swing) {
            return Optional.of(flipperSwing());
        }
        if (event instanceof PlayEvent.Captured || event instanceof PlayEvent.Sunk) {
            return Optional.of(capture());
        }
        if (event instanceof PlayEvent.Fired || event instanceof PlayEvent.Spawned) {
            return Optional.of(fire());
        }
        throw new IllegalArgumentException("no sound for " + event);
    }

    public static Optional<Cue> gizmoHit(GizmoKind kind, double impactSpeed) {
        return click(pitchOf(kind), impactSpeed);
    }

    public static Optional<Cue> wallHit(double impactSpeed) {
        return click(WALL_HZ, impactSpeed);
    }

    public static Optional<Cue> ballHit(double impactSpeed) {
        return click(BALL_HZ, impactSpeed);
    }

    public static Cue flipperSwing() {
        return new Cue(Cue.Kind.SWISH, 1, SWISH_GAIN);
    }

    public static Cue capture() {
        return new Cue(Cue.Kind.THUNK, 1, THUNK_GAIN);
    }

    public static Cue fire() {
        return new Cue(Cue.Kind.LAUNCH, 1, LAUNCH_GAIN);
    }

    static double pitchOf(GizmoKind kind) {
        return switch (kind) {
            case SQUARE -> 520;
            case TRIANGLE -> 700;
            case CIRCLE -> 880;
            case LEFT_FLIPPER, RIGHT_FLIPPER -> 330;
            case ABSORBER -> 160;
            case SINK -> 110;
            case ACCELERATOR -> 1100;
            case SPAWNER -> 440;
            case GATE -> 600;
            case DROP_TARGET -> 780;
            case SPINNER -> 392;
        };
    }

    private static Optional<Cue> click(double hz, double impactSpeed) {
        if (!(impactSpeed >= PlayEvent.Hit.REAL_IMPACT_SPEED)) {
            return Optional.empty();
        }
        return Optional.of(new Cue(Cue.Kind.CLICK, hz, Math.min(1, impactSpeed / FULL_SPEED)));
    }
}
