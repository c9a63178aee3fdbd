package gizmoball.model.loop;

import gizmoball.model.gizmo.BallTaking;
import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.Passage;

import java.util.ArrayList;
import java.util.List;

import physics.Vect;

/**
 * Stage 4 for a ball meeting a surface that does not move: an outer wall or a part of a still gizmo (docs/design.md,
 * "Resting and rolling contact"). The ball bounces with the surface's coefficient, comes to rest on it when it
 * approaches more slowly than the gravity pressing it in would explain, is wedged where a bounce would only go back
 * and forth among its contacts, is captured by an absorber, is taken out of play by a sink, leaves an accelerator
 * faster, or leaves by the pair of the portal whose mouth it meets (docs/design.md, "Portals").
 */
final class StillSurfaces {
    private final StepContext step;
    /** The surfaces a ball bounces among, the normals of the contacts taking a bounce: lists kept from use to use. */
    private final List<ContactRef> among = new ArrayList<>();
    private final List<Vect> taking = new ArrayList<>();
    /** The normals of a ball's other contacts, read at once by {@link StepContext#restingSpeed}: kept from use to use. */
    private final List<Vect> besides = new ArrayList<>();

    StillSurfaces(StepContext step) {
        this.step = step;
    }

    /** Resolves the ball's collision with the surface; returns what it hit. */
    TriggerSource resolve(Ball ball, Contact.StillSurface surface) {
        GizmoBase gizmo = surface.gizmo();
        if (gizmo != null) {
            gizmo.markTriggered(step.now());
        }
        Passage passage = Passages.of(step.view, ball, surface);
        TriggerSource struck = surface.struck();
        if (gizmo != null && gizmo.takesBalls()) {
            take(ball, gizmo);
        } else if (passage != null) {
            enter(ball, passage);
        } else {
            ContactRef ref = surface.ref();
            if (bounceOff(ball, surface, ref, struck, surface.normalTo(ball))) {
                bounceAmongContacts(ball, ref);
            }
        }
        return struck;
    }

    /**
     * The gizmo takes the ball (met in a collision, or touched when the tick begins by one that takes it out of play:
     * TickRun): an absorber captures it, a sink takes it out of play ({@link BallTaking}).
     */
    void take(Ball ball, GizmoBase gizmo) {
        step.actions.recordEvent(gizmo.ballTaking() == BallTaking.HOLDS
                ? new PlayEvent.Captured(gizmo.name(), ball.name(), ball.position())
                : new PlayEvent.Sunk(gizmo.name(), ball.name(), ball.position()));
        step.actions.take(ball, gizmo);
        step.energy.lost(ball);
        step.ballLeft(ball);
    }

    /**
     * The ball meets the open mouth of a portal with room beyond, at any speed: it leaves by the mouth of the pair,
     * touching it from outside ({@link Passage}); it forgets its contacts, the balls that lay on it theirs on it, and
     * what is near where it comes out wakes. (Where the room is taken, the mouth is a wall: {@link #resolve}.)
     */
    private void enter(Ball ball, Passage out) {
        step.actions.recordEvent(new PlayEvent.Teleported(out.entry(), out.exit(), ball.name(), ball.position(),
                out.centre()));
        ContactRef on = new ContactRef.OnBall(ball.name());
        List<Ball> others = step.view.balls();
        for (int b = 0; b < others.size(); b++) {
            Ball other = others.get(b);
            other.contacts().remove(on);
        }
        step.view.sleepers().wake(ball);   // and what slept on it: it has gone from under them
        ball.disturb();
        ball.moveTo(out.centre());
        ball.setVelocity(out.velocity());
        double margin = 4 * Arena.BALL_RADIUS;
        step.view.sleepers().wakeWithin(out.centre().x() - margin, out.centre().y() - margin,
                out.centre().x() + margin, out.centre().y() + margin);
        step.energy.lost(ball);   // its height changed: the shadow energy leaves it alone
        step.energy.mayGain(ball);
        step.ballMoved(ball);
    }

    /**
     * Resting contact or a bounce off a still surface, whose reference and trigger source the caller made once;
     * true if the ball bounced.
     */
    private boolean bounceOff(Ball ball, Contact.StillSurface surface, ContactRef ref, TriggerSource struck,
                              Vect normal) {
        double approach = -ball.velocity().dot(normal);
        if (approach <= step.restingSpeed(normal, step.contacts.normalsBesides(ball, ref, besides))) {
            step.comeToRest(ball, ref);
            return false;
        }
        double coefficient = surface.reflectionCoefficient();
        Vect bounced = surface.reflect(ball, ball.velocity(), coefficient);
        if (wedged(ball, ref, normal, bounced)) {
            step.comeToRest(ball, ref);
            return false;
        }
        GizmoBase gizmo = surface.gizmo();
        if (!step.reported.contains(ref)) {   // a bounce, not a rest: one hit per surface and collision
            step.reported.add(ref);
            step.actions.recordHit(ball, struck, gizmo == null ? null : gizmo.kind(), approach);
        }
        if (gizmo != null && gizmo.boosts()) {
            ball.setVelocity(gizmo.boost(bounced, Arena.MAX_SPEED));
            step.energy.lost(ball);   // it gained energy: the shadow energy leaves it alone
            step.energy.mayGain(ball);
            return true;
        }
        ball.setVelocity(bounced);
        step.energy.bounced(ball, normal, coefficient == 1.0);
        return true;
    }

    /**
     * A ball that has bounced off one still surface into another it lies on (a contact) meets it at once, and then
     * the first again: in a narrow wedge an elastic ball turns back only after about 180 / (the wedge's angle in
     * degrees) such bounces. They are the same bounces the loop would find one at a time at no time apart, resolved
     * here, each one a hit that triggers as any hit does (stage 5 takes them after this collision's own).
     */
    private void bounceAmongContacts(Ball ball, ContactRef from) {
        List<ContactRef> among = this.among;
        among.clear();
        List<ContactRef> contacts = ball.contacts();
        for (int i = 0; i < contacts.size(); i++) {   // by index: addAll would copy them into an array first
            among.add(contacts.get(i));
        }
        if (!among.contains(from)) {
            among.add(from);   // met just now, not lain on: the ball may come straight back to it
        }
        ContactRef last = from;
        for (int bounce = 0; bounce < step.settings.bouncesAmongContacts(); bounce++) {
            Contacts.Touch next = step.contacts.closing(ball, among, last);
            if (next == null) {
                return;
            }
            step.collisions++;
            step.zeroTimeCollisions++;
            GizmoBase gizmo = next.surface().gizmo();
            if (gizmo != null) {
                gizmo.markTriggered(step.now());
            }
            TriggerSource struck = next.surface().struck();
            step.alsoHit.add(struck);
            ContactRef ref = next.surface().ref();
            if (!bounceOff(ball, next.surface(), ref, struck, next.normal())) {
                return;
            }
            last = ref;
        }
        // Still bouncing: a wedge nearly flat (a flipper's face and a circle whose normals are 0.6 degrees from
        // opposite turned a ball only after thousands of bounces). Its limit is rest against what it bounces between.
        Contacts.Touch next = step.contacts.closing(ball, among, last);
        if (next != null) {
            step.comeToRest(ball, next.surface().ref());
        }
    }

    /**
     * Whether the bounce off a surface only wedges the ball between it and what it lies on: those contacts take the
     * bounce as resting contact (it meets each of them more slowly than it would bounce off), and what they leave of it
     * still closes on the surface. Bouncing would go on in turn between the two without end, each time slower; it ends
     * where the ball rests against both. A bounce fast enough to leave a contact is a bounce like any other.
     */
    private boolean wedged(Ball ball, ContactRef surface, Vect normal, Vect bounced) {
        List<Vect> taking = this.taking;
        taking.clear();
        List<ContactRef> refs = ball.contacts();
        for (int i = 0; i < refs.size(); i++) {
            ContactRef ref = refs.get(i);
            Vect held = ref.equals(surface) ? null : step.contacts.normal(ball, ref);
            if (held != null) {
                if (-bounced.dot(held) > step.restingSpeed(held, step.contacts.normalsBesides(ball, ref, besides))) {
                    return false;
                }
                taking.add(held);
            }
        }
        return !taking.isEmpty() && Contacts.project(bounced, taking).dot(normal) < -Tolerances.ROUNDING_SPEED;
    }
}
