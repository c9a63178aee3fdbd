package gizmoball.model.loop;

import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.MovingShape;
import gizmoball.model.gizmo.Shape;

import java.util.ArrayList;
import java.util.List;

import physics.Circle;
import physics.Geometry;
import physics.LineSegment;
import physics.Vect;

/**
 * Persistent contacts (docs/design.md, "Resting and rolling contact"): whether a ball still touches what it lies on,
 * the normals of those surfaces, and the velocity with every component pressing into them removed. A contact lasts
 * while the ball stays within {@link Tolerances#CONTACT} of the surface; it ends where a segment ends, where a
 * circle curves away from a ball moving straight on, or where the ball's velocity takes it off. A ball that loses a
 * contact looks for the surfaces it now touches, so a ball rolling over a seam passes from one face to the next
 * without a collision.
 * <p>Over 400 lines because a contact's whole life is one job (found, kept, its normal, ended), in stage 1 every tick.
 */
final class Contacts {

    private final LoopView view;
    /** A contact the ball has drifted off by less than this, slower than {@link #holdSpeed}, still holds. */
    private final double holdGap;
    private final double holdSpeed;
    private final Vect gravity;
    /** Which of a ball's contacts still hold, by place ({@link #keepHolding}), kept from ball to ball. */
    private boolean[] holds = new boolean[4];
    /** Where a ball's centre falls on a face, found again for each face looked at. */
    private final Foot foot = new Foot();
    /** The list {@link #normals(Ball)} fills. */
    private final List<Vect> queried = new ArrayList<>();
    /** The gizmos near a ball whose contacts are looked for: kept from use to use. */
    private final List<GizmoBase> nearby = new ArrayList<>();
    /** The gizmos near where a drifting ball would be put back (Room.at): kept, refilled per ask. */
    private final List<GizmoBase> inTheWay = new ArrayList<>();

    /**
     * A ball lying on something and nudged off it by a rounding of a wedge's projections, or rolling over a curve
     * slowly, drifts off by less than a tick of gravity would bring back ({@code g dt^2}), at less than half a tick of
     * gravity's speed: such a ball keeps the contact and loses that drift, as gravity would have done.
     */
    Contacts(LoopView view, Vect gravity, double dt) {
        this.view = view;
        this.gravity = gravity;
        double g = gravity.length();
        this.holdGap = Math.max(Tolerances.CONTACT, g * dt * dt);
        this.holdSpeed = g * dt / 2;
    }

    /**
     * Keeps the ball's contacts that still hold and returns their normals (unit, from the surface to the ball).
     * A ball found slightly inside one is put back to touching it. If a contact ended, the surfaces the ball touches
     * now become its contacts.
     */
    List<Vect> refresh(Ball ball) {
        List<Vect> normals = new ArrayList<>();
        refresh(ball, normals);
        return normals;
    }

    /** As {@link #refresh(Ball)}, into {@code normals}, emptied first (stage 1's list, kept from ball to ball). */
    void refresh(Ball ball, List<Vect> normals) {
        if (onACorner(ball)) {
            // the face a corner may be the end of is found and takes over, before the corner's hold can act
            discover(ball, null);
            List<ContactRef> refs = ball.contacts();
            for (int i = refs.size() - 1; i >= 0; i--) {
                if (isFlushCorner(refs, refs.get(i))) {
                    refs.remove(i);   // a corner's removal changes no face, so no other corner's test
                }
            }
        }
        normals.clear();
        if (keepHolding(ball, normals)) {
            discover(ball, normals);
            dropFlushCorners(ball, normals);
        }
    }

    /**
     * Keeps the ball's contacts that still hold, their normals added in order (each looked at once, the list as it
     * was, then the rest removed: as {@code removeIf} would, without making its lambda); true if one ended.
     */
    private boolean keepHolding(Ball ball, List<Vect> normals) {
        List<ContactRef> refs = ball.contacts();
        int n = refs.size();
        if (holds.length < n) {
            holds = new boolean[Math.max(n, 2 * holds.length)];
        }
        for (int i = 0; i < n; i++) {
            holds[i] = normalOf(ball, refs.get(i), normals, Look.HOLD) != null;
        }
        int kept = 0;
        for (int i = 0; i < n; i++) {
            if (holds[i]) {
                refs.set(kept++, refs.get(i));
            }
        }
        for (int i = n - 1; i >= kept; i--) {
            refs.remove(i);
        }
        return kept < n;
    }

    private boolean onACorner(Ball ball) {
        List<ContactRef> refs = ball.contacts();
        for (int i = 0; i < refs.size(); i++) {
            if (cornerOf(refs.get(i)) != null) {
                return true;
            }
        }
        return false;
    }

    /** Every still surface the ball touches now becomes a contact; returns the normals of all its contacts. */
    List<Vect> touchAll(Ball ball) {
        List<Vect> normals = refresh(ball);
        discover(ball, normals);
        dropFlushCorners(ball, normals);
        return normals;
    }

    /**
     * A corner (a circle of radius 0) lying on a face the ball also lies on is the end of that face, or of the face
     * beside it at a seam: flush with the surface, it adds nothing to it. Kept as a contact of its own it would,
     * once the ball rolls on past it, pull the ball back toward it (its normal tilts backwards) and slow it at
     * every seam. {@code normals} is in the order of the ball's contacts and stays so.
     */
    private void dropFlushCorners(Ball ball, List<Vect> normals) {
        List<ContactRef> refs = ball.contacts();
        for (int i = refs.size() - 1; i >= 0; i--) {
            if (isFlushCorner(refs, refs.get(i))) {
                refs.remove(i);
                normals.remove(i);
            }
        }
    }

    private boolean isFlushCorner(List<ContactRef> refs, ContactRef ref) {
        Vect corner = cornerOf(ref);
        return corner != null && onAFaceOf(refs, corner);
    }

    private boolean onAFaceOf(List<ContactRef> refs, Vect point) {
        for (int i = 0; i < refs.size(); i++) {
            ContactRef ref = refs.get(i);
            LineSegment face = faceOf(ref);
            if (face != null && Geometry.perpendicularPoint(face, point) != null
                    && point.distanceSquared(Geometry.perpendicularPointWholeLine(face, point))
                    <= Tolerances.CONTACT * Tolerances.CONTACT) {
                return true;
            }
        }
        return false;
    }

    /** The still segment a contact names; null for a circle, a ball or a part that is gone or swinging. */
    private LineSegment faceOf(ContactRef ref) {
        if (ref instanceof ContactRef.Wall wall) {
            return Arena.OUTER_WALLS.get(wall.side());
        }
        if (ref instanceof ContactRef.Part part && !part.circle()) {
            GizmoBase gizmo = stillGizmo(part);
            return gizmo == null || part.index() >= gizmo.shape().segments().size() ? null
                    : gizmo.shape().segments().get(part.index());
        }
        return null;
    }

    /** The point of a corner contact (a part's circle of radius 0); null for anything else. */
    private Vect cornerOf(ContactRef ref) {
        if (ref instanceof ContactRef.Part part && part.circle()) {
            GizmoBase gizmo = stillGizmo(part);
            if (gizmo != null && part.index() < gizmo.shape().circles().size()) {
                Circle circle = gizmo.shape().circles().get(part.index());
                return circle.getRadius() == 0 ? circle.getCenter() : null;
            }
        }
        return null;
    }

    private GizmoBase stillGizmo(ContactRef.Part part) {
        GizmoBase gizmo = view.gizmo(part.gizmo());
        return gizmo instanceof MovingShape moving && moving.isMoving() ? null : gizmo;
    }

    /**
     * The normals of the ball's contacts as they are now, without changing them: a list kept from call to call, which
     * the next call empties (each caller reads it before it asks again).
     */
    List<Vect> normals(Ball ball) {
        List<Vect> normals = queried;
        normals.clear();
        List<ContactRef> refs = ball.contacts();
        for (int i = 0; i < refs.size(); i++) {
            ContactRef ref = refs.get(i);
            normalOf(ball, ref, normals, Look.QUERY);
        }
        return normals;
    }

    /** A still surface the ball touches as a contact, with its normal there as the contact measures it. */
    record Touch(Contact.StillSurface surface, Vect normal) {
    }

    /**
     * One of {@code surfaces} other than {@code besides}, and other than a ball, that the ball touches and its
     * velocity closes on faster than rounding; null if there is none.
     */
    Touch closing(Ball ball, List<ContactRef> surfaces, ContactRef besides) {
        for (int i = 0; i < surfaces.size(); i++) {
            ContactRef ref = surfaces.get(i);
            if (ref.equals(besides) || ref instanceof ContactRef.OnBall) {
                continue;
            }
            Vect normal = normal(ball, ref);   // null too for a part of a shape now moving
            if (normal == null || ball.vx() * normal.x() + ball.vy() * normal.y() >= -Tolerances.ROUNDING_SPEED) {
                continue;
            }
            if (ref instanceof ContactRef.Wall wall) {
                return new Touch(new Contact.OuterWall(wall.side(), Arena.OUTER_WALLS.get(wall.side())),
                        normal);
            }
            ContactRef.Part part = (ContactRef.Part) ref;
            GizmoBase gizmo = view.gizmo(part.gizmo());
            Shape shape = gizmo.shape();
            return new Touch(part.circle() ? new Contact.Round(gizmo, part.index(), shape.circles().get(part.index()))
                    : new Contact.Face(gizmo, part.index(), shape.segments().get(part.index())), normal);
        }
        return null;
    }

    /** The normal of one of the ball's contacts as it is now; null if that contact has ended. */
    Vect normal(Ball ball, ContactRef ref) {
        return normalOf(ball, ref, null, Look.QUERY);
    }

    /**
     * The normals of the ball's contacts other than {@code surface}, as they are now, into {@code normals} (emptied
     * first; the caller's list, kept from use to use), which it returns.
     */
    List<Vect> normalsBesides(Ball ball, ContactRef surface, List<Vect> normals) {
        normals.clear();
        List<ContactRef> refs = ball.contacts();
        for (int i = 0; i < refs.size(); i++) {
            ContactRef ref = refs.get(i);
            if (!ref.equals(surface)) {
                normalOf(ball, ref, normals, Look.QUERY);
            }
        }
        return normals;
    }

    /** Adds a contact (if new). */
    static void attach(Ball ball, ContactRef ref) {
        if (!ball.contacts().contains(ref)) {
            ball.contacts().add(ref);
        }
    }

    /**
     * The velocity nearest to v that closes on none of the surfaces: unchanged if it closes on none, else with the
     * closing part along one normal removed if that leaves it closing on no other, else zero (wedged: in the plane,
     * two independent surfaces hold a ball still). {@link Projection} reckons it on the components.
     */
    static Vect project(Vect v, List<Vect> normals) {
        int along = Projection.of(v.x(), v.y(), normals);
        return along == Projection.CLOSES_ON_NONE ? v
                : new Vect(Projection.x(v.x(), v.y(), normals, along), Projection.y(v.x(), v.y(), normals, along));
    }

    /**
     * Whether a ball whose velocity after friction is {@code (vx, vy)} only slides on its contacts: they are all still
     * (no ball among them) and v closes on none faster than rounding, so projecting stage 1's velocity removes only
     * what gravity's kick pressed into them. Such a tick keeps the shadow energy (ShadowEnergy): along the surfaces
     * the kick is gravity's part along them, and the straight move never leaves them.
     */
    static boolean slidesOnStill(Ball ball, double vx, double vy, List<Vect> normals) {
        List<ContactRef> refs = ball.contacts();
        for (int i = 0; i < refs.size(); i++) {
            if (refs.get(i) instanceof ContactRef.OnBall) {
                return false;
            }
        }
        for (int i = 0; i < normals.size(); i++) {
            Vect n = normals.get(i);
            if (vx * n.x() + vy * n.y() < -Tolerances.ROUNDING_SPEED) {
                return false;
            }
        }
        return true;
    }

    /**
     * How a look at a contact may change the ball: a query changes nothing; a look that keeps or finds contacts puts a
     * ball found slightly inside back to touching and, {@code HOLD}, one that has only just drifted off back onto
     * the surface (see the constructor).
     */
    private enum Look {
        QUERY, SNAP, HOLD
    }

    /**
     * Adds the normal of a contact that still holds to {@code normals} (unless that is null) and returns it; null if
     * it has ended.
     */
    private Vect normalOf(Ball ball, ContactRef ref, List<Vect> normals, Look look) {
        Vect normal;
        if (ref instanceof ContactRef.Wall wall) {
            normal = onSegment(ball, Arena.OUTER_WALLS.get(wall.side()), look);
        } else if (ref instanceof ContactRef.Part part) {
            normal = onPart(ball, part, look);
        } else {
            normal = onBall(ball, (ContactRef.OnBall) ref, look);
        }
        if (normal != null && normals != null) {
            normals.add(normal);
        }
        return normal;
    }

    private Vect onPart(Ball ball, ContactRef.Part part, Look look) {
        return onPart(ball, view.gizmo(part.gizmo()), part.circle(), part.index(), look);
    }

    /** The contact with circle or segment {@code index} of the gizmo's shape (null: no gizmo); null if none. */
    private Vect onPart(Ball ball, GizmoBase gizmo, boolean circle, int index, Look look) {
        if (gizmo == null || gizmo instanceof MovingShape moving && moving.isMoving()
                && !(circle && moving.turnsInPlace(index))) {
            return null;   // a moving shape holds nothing up, but a round end it turns in place does not move
        }
        if (!circle && Passages.through(view, ball, gizmo, index) != null) {
            return null;   // an open mouth with room beyond holds nothing up: the ball goes through
        }
        Shape shape = gizmo.shape();
        if (circle) {
            return index < shape.circles().size() ? onCircle(ball, shape.circles().get(index), look) : null;
        }
        return index < shape.segments().size() ? onSegment(ball, shape.segments().get(index), look) : null;
    }

    private Vect onBall(Ball ball, ContactRef.OnBall on, Look look) {
        Ball other = view.ball(on.ball());
        return other == null || !supports(other, ball) ? null : onCircle(ball, other.circle(), look);
    }

    /**
     * A ball supports another while it lies still (asleep) or lies on something other than that ball: two balls
     * leaning only on each other hold nothing up.
     */
    static boolean supports(Ball support, Ball ball) {
        if (support.isCaptured()) {
            return false;
        }
        if (support.isAsleep()) {
            return true;
        }
        ContactRef back = ball.asSupported();
        List<ContactRef> refs = support.contacts();
        for (int i = 0; i < refs.size(); i++) {
            if (!refs.get(i).equals(back)) {
                return true;
            }
        }
        return false;
    }

    /** The contact with the segment at the foot of the perpendicular from the ball's centre; none past its ends. */
    private Vect onSegment(Ball ball, LineSegment segment, Look look) {
        if (!foot.on(segment, ball.x(), ball.y())) {
            return null;   // past the end: the corner circle or the next face takes over
        }
        return touching(ball, foot.x, foot.y, 0, look);
    }

    private Vect onCircle(Ball ball, Circle circle, Look look) {
        Vect centre = circle.getCenter();
        return touching(ball, centre.x(), centre.y(), circle.getRadius(), look);
    }

    /**
     * The normal away from a surface point (or circle centre) {@code (fromX, fromY)} the ball touches, or null.
     * Unless the look is a query, a ball found slightly inside is put back to touching; on a {@code HOLD}, one that
     * drifted off by more than the contact tolerance but less than the hold gap, slowly, from a surface below or
     * beside it (gravity does not pull it away), keeps the contact and loses the drift, and is put back onto the
     * surface where that pushes it into nothing else; where it would, it lies a hair above the surface instead (at
     * most g dt^2). A ball left hovering would sit still in mid-air, a visible gap under a resting ball. The offset
     * from the point is reckoned on the components, as {@code Vect}'s minus and length would.
     */
    private Vect touching(Ball ball, double fromX, double fromY, double radius, Look look) {
        double offsetX = ball.x() - fromX + 0.0;
        double offsetY = ball.y() - fromY + 0.0;
        double distance = Components.length(offsetX, offsetY);
        double touch = radius + Arena.BALL_RADIUS;
        if (distance == 0 || distance - touch > (look == Look.HOLD ? holdGap : Tolerances.CONTACT)) {
            return null;
        }
        KnownNormals known = ball.knownNormals();
        Vect normal = known.find(ball.x(), ball.y(), fromX, fromY);
        if (normal == null) {
            double inverse = 1 / distance;
            double nx = offsetX * inverse + 0.0;   // as new Vect(offsetX * inverse, offsetY * inverse) holds them
            double ny = offsetY * inverse + 0.0;
            normal = known.same(nx, ny);
            if (normal == null) {
                normal = new Vect(nx, ny);
            }
            known.keep(ball.x(), ball.y(), fromX, fromY, normal);
        }
        if (look == Look.QUERY) {
            return normal;
        }
        if (distance - touch > Tolerances.CONTACT) {
            double leaving = ball.vx() * normal.x() + ball.vy() * normal.y();
            if (leaving > holdSpeed || normal.dot(gravity) > 0) {
                return null;
            }
            ball.setVelocity(ball.velocity().minus(normal.times(Math.max(0, leaving))));
            Vect onSurface = new Vect(fromX, fromY).plus(normal.times(touch));
            if (Room.at(view, ball, onSurface, inTheWay)) {
                ball.moveTo(onSurface);
            }
        } else if (touch - distance > Tolerances.SNAP_DEPTH) {
            ball.moveTo(new Vect(fromX, fromY).plus(normal.times(touch)));
        }
        return normal;
    }

    /** Every still surface the ball touches now becomes a contact of it. */
    private void discover(Ball ball, List<Vect> normals) {
        for (int side = 0; side < Arena.OUTER_WALLS.size(); side++) {
            consider(ball, ContactRef.Wall.of(side), normals);
        }
        double reach = Arena.BALL_RADIUS + Tolerances.CONTACT;
        List<GizmoBase> nearby = this.nearby;
        view.index().within(ball.x() - reach, ball.y() - reach, ball.x() + reach, ball.y() + reach, nearby);
        for (int g = 0; g < nearby.size(); g++) {
            GizmoBase gizmo = nearby.get(g);
            if (gizmo.takesBalls() || gizmo instanceof MovingShape moving && moving.isMoving()) {
                continue;   // an absorber or a sink takes what touches it; a moving shape is no support
            }
            Shape shape = gizmo.shape();
            for (int i = 0; i < shape.segments().size(); i++) {
                considerPart(ball, gizmo, false, i, normals);
            }
            for (int i = 0; i < shape.circles().size(); i++) {
                considerPart(ball, gizmo, true, i, normals);
            }
        }
    }

    private void consider(Ball ball, ContactRef ref, List<Vect> normals) {
        if (!ball.contacts().contains(ref) && normalOf(ball, ref, normals, Look.SNAP) != null) {
            ball.contacts().add(ref);
        }
    }

    /** As {@link #consider} for a part of the gizmo, whose reference is made only when it becomes a contact. */
    private void considerPart(Ball ball, GizmoBase gizmo, boolean circle, int index, List<Vect> normals) {
        List<ContactRef> refs = ball.contacts();
        for (int i = 0; i < refs.size(); i++) {
            if (refs.get(i) instanceof ContactRef.Part part && part.circle() == circle && part.index() == index
                    && part.gizmo().equals(gizmo.name())) {
                return;
            }
        }
        Vect normal = onPart(ball, gizmo, circle, index, Look.SNAP);
        if (normal != null) {
            if (normals != null) {
                normals.add(normal);
            }
            refs.add(new ContactRef.Part(gizmo.name(), circle, index));
        }
    }
}
