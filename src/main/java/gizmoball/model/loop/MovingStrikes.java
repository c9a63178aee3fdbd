package gizmoball.model.loop;

import gizmoball.model.gizmo.MovingShape;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import physics.Vect;

/**
 * Stage 4 for a ball a moving shape strikes (docs/design.md, "Moving shapes" and "Pinched balls"), with what each
 * tick remembers of its strikes: how often each shape struck each ball, what the ball met in between, and the
 * squeezes and pushes those make. A ball the shape cannot push out of a pocket stalls it (a jam).
 */
final class MovingStrikes {
    /** A ball and a moving shape, for counting how often the shape strikes the ball within one tick. */
    private record Strike(Ball ball, MovingShape shape) {
    }

    private final StepContext step;
    /** SEED: balls a moving shape struck this tick, which move on to the end of it. */
    private final Set<Ball> carried = new HashSet<>();
    private final Map<Strike, Integer> strikes = new HashMap<>();
    /** Balls that met something else since a moving shape last struck them in this tick (struck balls only). */
    private final Set<Ball> metSinceStrike = new HashSet<>();
    /** What each ball struck by a moving shape in this tick has met since then, other than moving shapes. */
    private final Map<Ball, Set<Contact>> metAfterStrike = new HashMap<>();
    /** The part of a moving shape that last struck each ball in this tick. */
    private final Map<Ball, Contact.MovingPart> lastStrike = new HashMap<>();
    /** How often a squeeze has sent each ball out between a shape and what it came back from, in this tick. */
    private final Map<Ball, Integer> squeezed = new HashMap<>();

    MovingStrikes(StepContext step) {
        this.step = step;
    }

    /** A tick starts: no ball has been struck or carried yet. */
    void begin() {
        carried.clear();
        strikes.clear();
        metSinceStrike.clear();
        metAfterStrike.clear();
        lastStrike.clear();
        squeezed.clear();
    }

    /** A stalled shape goes on once no ball touches it any more, and wakes what fell asleep in its way. */
    void releaseStalled() {
        List<MovingShape> shapes = step.view.movingShapes();
        for (int i = 0; i < shapes.size(); i++) {
            MovingShape moving = shapes.get(i);
            if (moving.isStalled() && !touchedByABall(moving)) {
                moving.release();
                step.actions.wakeSweep(moving);
            }
        }
    }

    /**
     * Whether a free ball touches the shape. Only a ball whose centre lies in the shape's box widened by a ball is
     * measured: a shape stalled by a ball that then fell asleep against it is asked about at every tick, and measuring
     * every ball of the board against it cost stress.txt 60 us a tick when nothing else moved.
     */
    private boolean touchedByABall(MovingShape moving) {
        double touch = Arena.BALL_RADIUS + Tolerances.CONTACT;
        List<Ball> balls = step.view.balls();
        for (int b = 0; b < balls.size(); b++) {
            Ball ball = balls.get(b);
            double x = ball.x();
            double y = ball.y();
            if (!ball.isCaptured() && x >= moving.x() - touch && x <= moving.x() + moving.width() + touch
                    && y >= moving.y() - touch && y <= moving.y() + moving.height() + touch
                    && moving.signedDistance(ball.position()) <= touch) {
                return true;
            }
        }
        return false;
    }

    /** Whether a moving shape's box, widened by a ball, holds the ball: it may not sleep there. */
    boolean nearMoving(Ball ball) {
        double r = 2 * Arena.BALL_RADIUS;
        double x = ball.x();
        double y = ball.y();
        List<MovingShape> shapes = step.view.movingShapes();
        for (int i = 0; i < shapes.size(); i++) {
            MovingShape moving = shapes.get(i);
            if (moving.isMoving() && x > moving.x() - r && x < moving.x() + moving.width() + r
                    && y > moving.y() - r && y < moving.y() + moving.height() + r) {
                return true;
            }
        }
        return false;
    }

    /** SEED: whether a moving shape struck the ball in this tick, so it moves on to the end of it. */
    boolean carries(Ball ball) {
        return carried.contains(ball);
    }

    /** The ball met a surface other than a moving shape: noted only for a ball a moving shape has struck. */
    void met(Ball ball, Contact surface) {
        Set<Contact> met = metAfterStrike.isEmpty() ? null : metAfterStrike.get(ball);
        if (met != null) {
            metSinceStrike.add(ball);
            met.add(surface);
        }
    }

    /**
     * The part strikes the ball: it is batted with physics-lib's rotating reflection; a ball struck again after it came
     * back from something is squeezed out between them ({@link Squeeze}), one struck again with nothing in between is
     * pushed, and one that cannot leave stalls the shape. Returns what struck it.
     */
    TriggerSource resolve(Ball ball, Contact.MovingPart part) {
        MovingShape moving = part.shape();
        moving.markTriggered(step.now());
        step.energy.lost(ball);
        step.energy.mayGain(ball);
        step.finished.remove(ball);   // SEED too: a moving shape carries the ball on, it cannot stand in its way
        carried.add(ball);
        Vect before = ball.velocity();
        Contact.MovingPart previous = lastStrike.put(ball, part);
        if (previous != null && previous.shape() != moving) {
            met(ball, previous);   // struck by another shape since: it came back from that one
        }
        boolean cameBack = metSinceStrike.remove(ball);
        Set<Contact> met = metAfterStrike.computeIfAbsent(ball, struck -> new LinkedHashSet<>());
        int strike = strikes.merge(new Strike(ball, moving), 1, Integer::sum);
        LoopSettings settings = step.settings;
        Vect reflected = strike >= settings.strikesOfAPush() && !cameBack
                ? pushed(before, part.reflect(ball.circle(), Vect.ZERO))
                : part.reflect(ball.circle(), before);
        boolean squeezedOut = strike >= settings.strikesOfASqueeze() && cameBack;
        boolean endless = squeezedOut && squeezed.merge(ball, 1, Integer::sum) > settings.squeezesBeforePinched();
        Optional<Vect> leaving = squeezedOut && !endless
                ? Squeeze.leaving(reflected, squeezeSides(ball, part, met, reflected))
                : Optional.of(reflected);
        ball.setVelocity(endless ? Vect.ZERO : leaving.orElse(Vect.ZERO));
        step.actions.recordHit(ball, part.struck(), moving.kind(), ball.velocity().minus(before).length() / 2);
        if (endless) {
            step.pinched++;   // guard (counted): squeezed out and back again without end
            stall(ball, moving);
        } else if (leaving.isEmpty()) {
            step.actions.recordEvent(new PlayEvent.Jammed(moving.name(), ball.name()));
            stall(ball, moving);
        }
        return part.struck();
    }

    /**
     * What a squeezed ball must leave: the shape where it strikes, what the ball lies on, and everything it has met
     * since the shape first struck it in this tick, each taken where the ball is now.
     */
    private List<Squeeze.Side> squeezeSides(Ball ball, Contact.MovingPart part, Set<Contact> met, Vect reflected) {
        List<Squeeze.Side> sides = new ArrayList<>();
        Vect centre = ball.position();
        // The striking shape: the ball must leave it at least as fast along the normal as its bounce does. Leaving
        // at only the surface's own speed would keep the ball on a surface that turns, and so speeds up under it
        // further out: struck again at once, without end.
        Squeeze.Side striking = part.side(centre, step.detector::motion);
        sides.add(new Squeeze.Side(striking.normal(),
                Math.max(striking.speed(), reflected.dot(striking.normal()))));
        step.contacts.normals(ball).forEach(normal -> sides.add(new Squeeze.Side(normal, 0)));
        met.forEach(surface -> sides.add(surface.side(centre, step.detector::motion)));
        return sides;
    }

    /**
     * A ball the shape keeps striking with nothing in between is being pushed: each bounce leaves it a little
     * slower than the surface further out, which meets it again at once, without end. It is batted as a ball at
     * rest would be (the normal velocity a still ball would take), keeping its sliding along the surface, and so
     * leaves the surface for good.
     */
    private static Vect pushed(Vect before, Vect fromRest) {
        double speed = fromRest.length();
        if (speed == 0) {
            return before;
        }
        Vect normal = fromRest.times(1 / speed);
        return before.minus(normal.times(before.dot(normal))).plus(fromRest);
    }

    /**
     * The ball jams the shape: no velocity within {@link Arena#MAX_SPEED} leaves both it and what the ball is
     * squeezed against (a {@link Squeeze}). The shape stops where it is, a stall, as a real flipper's motor does;
     * the ball stops where the shape met it and keeps everything it touches as contacts. The shape goes on once no
     * ball touches it, or when it is sent another way.
     */
    private void stall(Ball ball, MovingShape moving) {
        moving.stall();
        step.contacts.touchAll(ball);
        ball.setVelocity(Vect.ZERO);
        step.movingShapeChanged(moving);
    }
}
