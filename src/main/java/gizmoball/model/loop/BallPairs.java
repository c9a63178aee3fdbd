package gizmoball.model.loop;

import java.util.ArrayList;
import java.util.List;

import physics.Vect;

/**
 * Stage 4 for two balls meeting (docs/design.md, "The tick"): an elastic bounce, or, where they meet slowly and one of
 * them is held up, a pile that settles.
 */
final class BallPairs {
    private final StepContext step;

    /** The normals of what else holds each ball of a pair pressed together: lists kept from use to use. */
    private final List<Vect> holdingBall = new ArrayList<>();
    private final List<Vect> holdingOther = new ArrayList<>();
    /** A bounce's velocities, reckoned afresh for each bounce. */
    private final BallBounce bounce = new BallBounce();

    BallPairs(StepContext step) {
        this.step = step;
    }

    /**
     * Balls that meet more slowly than two ticks of gravity, one of them lying on something (asleep, or in persistent
     * contact), are pressed together in a pile, not bouncing: each that meets a supported ball stops closing on it and
     * keeps it as a contact, as it would on a floor, and a floor feels nothing. So piles build from the bottom and
     * settle. Otherwise the two bounce elastically, and a sleeping one wakes.
     */
    Struck resolve(Ball ball, Ball other) {
        step.energy.mayGain(ball);   // energy moves between them
        step.energy.mayGain(other);
        // ball.position().minus(other.position()).unitSize() (Components.unit), and the approach along it, on the
        // components: a bounce makes no normal vector
        double dx = ball.x() - other.x() + 0.0;
        double dy = ball.y() - other.y() + 0.0;
        double length = Components.length(dx, dy);
        double normalX = Components.unitPart(dx, length);
        double normalY = Components.unitPart(dy, length);
        double rx = ball.vx() - step.detector.motionX(other) + 0.0;   // ball.velocity().minus(motion(other))
        double ry = ball.vy() - step.detector.motionY(other) + 0.0;
        double approach = -(rx * normalX + ry * normalY);
        boolean slow = approach <= step.pressingSpeed();
        Struck.OtherBall struck = other.asStruck();
        if (slow && (Contacts.supports(other, ball) || Contacts.supports(ball, other))) {
            restAgainst(ball, other);
            restAgainst(other, ball);
            Vect normal = new Vect(normalX, normalY);
            if (-ball.velocity().minus(other.velocity()).dot(normal) > Tolerances.ROUNDING_SPEED) {
                pressTogether(ball, other, normal);
            }
            step.restingContact = true;
            return struck;
        }
        step.actions.recordHit(ball, struck, null, approach);
        other.setStillTime(0);
        if (other.isAsleep()) {
            // What it wakes is at rest still, as every ball's known collisions took it: only the ball this bounce
            // sets moving is asked again (with those whose next collision was with it), as after any bounce; the
            // balls woken under it, never asked while asleep, ask when the schedule next looks.
            step.view.sleepers().wake(other);
            step.findAwake();
        }
        bounce.between(ball.x(), ball.y(), ball.vx(), ball.vy(), other.x(), other.y(), other.vx(), other.vy());
        ball.setVelocity(bounce.firstX, bounce.firstY);
        other.setVelocity(bounce.secondX, bounce.secondY);
        step.energy.bounced(ball, normalX, normalY);
        step.energy.bounced(other, -normalX + 0.0, -normalY + 0.0);   // normal.neg()
        step.energy.met(ball, other);
        return struck;
    }

    /**
     * The support itself moves into the ball: they go on together along the normal, momentum kept, and neither
     * presses into what else holds it (the support's floor takes what the support cannot). Each of those steps may
     * undo a little of the other, so they repeat until the pair closes no faster than rounding: the fixed point
     * the loop would otherwise reach only through a chain of zero-time collisions, one step each.
     */
    private void pressTogether(Ball ball, Ball other, Vect normal) {
        List<Vect> holdingBall = step.contacts.normalsBesides(ball, other.asSupported(), this.holdingBall);
        List<Vect> holdingOther = step.contacts.normalsBesides(other, ball.asSupported(), this.holdingOther);
        for (int i = 0; i < step.settings.pressSteps()
                && -ball.velocity().minus(other.velocity()).dot(normal) > Tolerances.ROUNDING_SPEED; i++) {
            double common = (ball.velocity().dot(normal) + other.velocity().dot(normal)) / 2;
            ball.setVelocity(Contacts.project(ball.velocity().plus(normal.times(common - ball.velocity().dot(normal))),
                    holdingBall));
            other.setVelocity(Contacts.project(
                    other.velocity().plus(normal.times(common - other.velocity().dot(normal))), holdingOther));
        }
        step.energy.lost(ball);
        step.energy.lost(other);
    }

    /** The ball, awake, stops closing on a supporting ball and keeps it as a contact. */
    void restAgainst(Ball ball, Ball support) {
        if (!ball.isAsleep() && Contacts.supports(support, ball)) {
            step.comeToRest(ball, new ContactRef.OnBall(support.name()));
        }
    }
}
