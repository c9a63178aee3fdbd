package gizmoball.model.loop;

import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.MovingShape;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Function;
import java.util.function.Predicate;

import physics.Vect;

/**
 * Stage 4 for a collision that must be solved with everything its balls touch at once (docs/design.md, "Contact
 * clusters"): which collisions those are, and the simultaneous solve of the cluster's normal impulses with its hits,
 * rests and stalls.
 */
final class ClusterSolve {

    private final StepContext step;
    /** The balls filed near a ball, where they are now: what a cluster asks for the balls touching its own. */
    private final ContactCluster.Near near;
    /** What the cluster asks of its balls, made once: each ball's motion, and whether a ball may join (unfinished). */
    private final Function<Ball, Vect> motion;
    private final Predicate<Ball> movable;
    /** The collision's ball or two, from which a cluster is gathered: kept, refilled per solve. */
    private final List<Ball> seeds = new ArrayList<>(2);
    /** The cluster to solve, gathered anew for each collision that needs one into the same lists. */
    private final ContactCluster cluster = new ContactCluster();
    /** The solver, its rows and arrays kept from one cluster to the next (grown to the largest seen). */
    private final NormalImpulses impulses;
    // Kept too, and grown likewise: per ball, the velocities a solve starts from; per row, the impact speeds; one
    // row's other normals on its ball; the elastic bounces' books.
    private double[] startX = new double[0];
    private double[] startY = new double[0];
    private double[] impact = new double[0];
    private final List<Vect> otherNormals = new ArrayList<>();
    private final ElasticBounces elasticBounces;
    /** The moving shapes a solve stalled, and the surfaces its impacts were heard from: kept, emptied per solve. */
    private final Set<MovingShape> stalled = new LinkedHashSet<>();
    private final HeardSurfaces heard = new HeardSurfaces();

    ClusterSolve(StepContext step) {
        this.step = step;
        this.near = (ball, within, into) -> step.schedule.filedNear(ball, within, step.elapsed, into);
        this.motion = ball -> step.detector.motion(ball);
        this.movable = candidate -> !step.finished.contains(candidate);
        this.impulses = new NormalImpulses(step.settings);
        this.elasticBounces = new ElasticBounces(step.energy);
    }

    /**
     * The cluster of touching contacts a collision must be solved with at once, or null when the collision is a
     * contact of its own. A collision at the very moment of a ball's last one is a chain through touching contacts;
     * one simultaneous solve ends it, where one contact at a time would go on at no time apart. A ball that has
     * collided {@link LoopSettings#rattleCollisions()} times in the tick and again within
     * {@link LoopSettings#rattleTime()} is rattling between surfaces it nearly touches (a ball in the apex of a narrow
     * pocket, without gravity to settle it): the surfaces within twice the way it went since count as touching it,
     * so one solve ends the rattle as well.
     */
    ContactCluster toSolve(Collision collision) {
        Contact contact = collision.contact();
        // What touches an absorber or a sink, on a face or at a corner, is taken, never a contact of a cluster; what
        // meets the open mouth of a portal with room beyond passes through it.
        if (step.view.loopMode() != LoopMode.CONTINUOUS || contact instanceof Contact.StillSurface surface
                && surface.gizmo() != null && surface.gizmo().takesBalls()
                || Passages.of(step.view, collision.ball(), contact) != null) {
            return null;
        }
        Ball ball = collision.ball();
        Ball other = collision.otherBall();
        double reach;
        if (again(ball) || other != null && again(other)) {
            reach = Tolerances.PLACEMENT;
        } else if (rattling(ball)) {
            reach = Math.min(step.settings.rattleReach(),
                    2 * ball.velocity().length() * (step.elapsed - step.lastCollisionAt(ball)));
        } else {
            return null;
        }
        seeds.clear();
        seeds.add(ball);
        if (other != null) {
            seeds.add(other);
        }
        return cluster.gather(step.view, seeds, near, motion, movable, reach, step.settings);
    }

    private boolean rattling(Ball ball) {
        double last = step.lastCollisionAt(ball);
        return !Double.isNaN(last) && step.elapsed - last <= step.settings.rattleTime()
                && step.collisionsOf(ball) >= step.settings.rattleCollisions();
    }

    private boolean again(Ball ball) {
        double last = step.lastCollisionAt(ball);
        return !Double.isNaN(last) && step.elapsed - last <= step.settings.zeroTime();
    }

    /**
     * Solves the cluster's normal impulses at once ({@link NormalImpulses}): no contact is left closing, each impact
     * bounces with its coefficient where the contacts allow it, moving shapes give velocity and take none. Where
     * no velocity within {@link Arena#MAX_SPEED} leaves the moving parts, they stall (a jam) and the cluster is
     * solved again with them still. Every impact is a hit that triggers; a slow one is resting contact.
     */
    Struck resolve(Collision collision, ContactCluster cluster) {
        List<Ball> balls = cluster.balls();
        boolean carried = carried(collision);
        Solved solved = solveTakingGrazes(cluster, Set.of(), carried);
        stalled.clear();
        if (!solved.result().feasible()) {
            for (ClusterRow row : cluster.rows()) {
                if (row.other() instanceof ClusterRow.Other.Moving moving && stalled.add(moving.shape())) {
                    moving.shape().stall();
                    step.actions.recordEvent(new PlayEvent.Jammed(moving.shape().name(),
                            balls.get(row.ball()).name()));
                }
            }
            solved = solveTakingGrazes(cluster, stalled, carried);
        }
        NormalImpulses.Result result = solved.result();
        double[] impact = solved.impact();
        boolean elastic = stalled.isEmpty() && !carried && keepsEnergy(cluster, impact, result);
        boolean woke = false;
        for (int k = 0; k < balls.size(); k++) {
            Ball ball = balls.get(k);
            step.energy.mayGain(ball);   // energy moves between its balls, and moving shapes may give some
            double beforeX = step.detector.motionX(ball);
            double beforeY = step.detector.motionY(ball);
            double afterX = result.vx()[k] + 0.0;   // as a Vect holds it
            double afterY = result.vy()[k] + 0.0;
            if (Double.compare(afterX, beforeX) == 0 && Double.compare(afterY, beforeY) == 0) {
                continue;
            }
            if (ball.isAsleep()) {
                step.view.sleepers().wake(ball);
                woke = true;
            }
            ball.setVelocity(afterX, afterY);
            ball.setStillTime(0);
            if (!elastic) {
                step.energy.lost(ball);
            }
            if (movedOnlyByRounding(beforeX, beforeY, afterX, afterY)) {
                step.schedule.sped(ball, step.elapsed);   // its known collisions stand: they move by less than rounding
            } else {
                step.changed(ball);
            }
        }
        if (elastic) {
            elasticBounces.note(cluster, result.compression());
        }
        Struck hit = noteImpacts(collision, cluster, impact, result);
        if (woke) {
            // What it woke lies still, as every known collision took it; what the solve set moving was asked again
            // above, and the balls woken under it, never asked while asleep, ask when the schedule next looks.
            step.findAwake();
        }
        if (!stalled.isEmpty()) {   // (an iterator over none would still be made)
            for (MovingShape shape : stalled) {
                step.movingShapeChanged(shape);
            }
        }
        return hit;
    }

    /**
     * Whether the solve changed a ball's velocity by no more than {@link Tolerances#ROUNDING_SPEED}: the last bits of
     * a velocity the rows did not move (half the members of the clusters of a pile of 100 balls). Such a ball is not
     * asked again: over what is left of the tick its path is off by less than 2e-11 L, its known collisions by as
     * little, and what it was to meet stays met; the next tick asks about every ball afresh.
     */
    private static boolean movedOnlyByRounding(double beforeX, double beforeY, double afterX, double afterY) {
        double dx = afterX - beforeX;   // |after - before|, a plain square root as in CollisionDetector.speedOf
        double dy = afterY - beforeY;
        return Math.sqrt(dx * dx + dy * dy) <= Tolerances.ROUNDING_SPEED;
    }

    /**
     * Whether the solve kept the cluster's kinetic energy as elastic bounces do: every contact it pressed was an
     * impact with a still surface of coefficient 1 or another ball of the cluster, and the balls' |v|^2 summed is what
     * it was, to rounding (simultaneous impacts with restitution 1 need not keep it). Then the bounces keep the
     * shadow energy as single elastic bounces do, and their timing is corrected like theirs (ShadowEnergy).
     */
    private boolean keepsEnergy(ContactCluster cluster, double[] impact, NormalImpulses.Result result) {
        List<ClusterRow> rows = cluster.rows();
        for (int i = 0; i < rows.size(); i++) {
            ClusterRow row = rows.get(i);
            if (result.compression()[i] > 0 && (result.compression()[i] <= impact[i] || row.restitution() != 1.0
                    || row.other() instanceof ClusterRow.Other.Moving)) {
                return false;
            }
        }
        double before = 0;
        double after = 0;
        List<Ball> balls = cluster.balls();
        for (int k = 0; k < balls.size(); k++) {
            double vx = step.detector.motionX(balls.get(k));   // motion(ball).dot(itself)
            double vy = step.detector.motionY(balls.get(k));
            before += vx * vx + vy * vy;
            after += result.vx()[k] * result.vx()[k] + result.vy()[k] * result.vy()[k];
        }
        return Math.abs(after - before) <= Tolerances.KEPT_ENERGY * before;
    }

    /**
     * Whether the collision is a ball rattling ({@link #rattling}): struck back and forth across gaps ever smaller
     * between what it nearly touches, in a pocket almost closed, or closing on it as a moving shape swings in (each
     * strike of which sends it back faster). Bounce by bounce the rattle would go on for ever, or faster and faster;
     * its limit is the ball at rest against what it rattles between, carried along by what moves, which is what the
     * solve gives it: every contact of the cluster inelastic. It loses energy and gains none.
     */
    private boolean carried(Collision collision) {
        return rattling(collision.ball());
    }

    /** A solve's answer with the impact speeds of the rows it was solved with. */
    private record Solved(NormalImpulses.Result result, double[] impact) {
    }

    /**
     * Solves the cluster; where the answer turns a ball into a contact it grazed, that contact becomes a row and the
     * cluster is solved again from the start ({@link ContactCluster#takeClosingGrazes}). Each round takes at least one
     * graze, so it ends.
     */
    private Solved solveTakingGrazes(ContactCluster cluster, Set<MovingShape> stalled, boolean carried) {
        while (true) {
            double[] impact = impactSpeeds(cluster);
            NormalImpulses.Result result = solve(cluster, impact, stalled, carried);
            if (!cluster.takeClosingGrazes(result.vx(), result.vy())) {
                return new Solved(result, impact);
            }
        }
    }

    private NormalImpulses.Result solve(ContactCluster cluster, double[] impact, Set<MovingShape> stalled,
                                        boolean carried) {
        List<ClusterRow> rows = cluster.rows();
        List<Ball> balls = cluster.balls();
        impulses.clear(balls.size());
        for (int i = 0; i < rows.size(); i++) {
            ClusterRow row = rows.get(i);
            boolean still = row.other() instanceof ClusterRow.Other.Moving moving
                    && stalled.contains(moving.shape());
            impulses.row(row.ball(), row.other() instanceof ClusterRow.Other.InCluster in ? in.index() : -1,
                    row.normalX(), row.normalY(), still ? 0 : row.surfaceSpeed(),
                    carried ? 0 : row.restitution());
        }
        if (startX.length < balls.size()) {
            startX = new double[balls.size()];
            startY = new double[balls.size()];
        }
        for (int k = 0; k < balls.size(); k++) {
            startX[k] = step.detector.motionX(balls.get(k));
            startY[k] = step.detector.motionY(balls.get(k));
        }
        return impulses.solve(startX, startY, impact, Arena.MAX_SPEED);
    }

    /**
     * The closing speed above which a contact of a cluster is an impact that bounces, as for a single contact
     * ({@link StepContext#restingSpeed}): the gravity pressing the ball into a surface as the ball's other contacts in
     * the cluster leave it, so a ball set on a floor settles, one pressed into a surface above or beside it by no
     * gravity bounces; between balls, as for two balls alone ({@link StepContext#pressingSpeed}).
     */
    private double[] impactSpeeds(ContactCluster cluster) {
        List<ClusterRow> rows = cluster.rows();
        if (impact.length < rows.size()) {
            impact = new double[Math.max(rows.size(), 2 * impact.length)];
        }
        for (int i = 0; i < rows.size(); i++) {
            ClusterRow row = rows.get(i);
            if (row.other() instanceof ClusterRow.Other.Surface) {
                otherNormals.clear();
                for (int j = 0; j < rows.size(); j++) {
                    if (j != i && rows.get(j).ball() == row.ball()) {
                        otherNormals.add(rows.get(j).normal());
                    }
                }
                impact[i] = step.restingSpeed(row.normal(), otherNormals);
            } else {
                impact[i] = step.pressingSpeed();
            }
        }
        return impact;
    }

    /**
     * The hits of a solved cluster (each contact whose impulse was an impact, once per surface) for the sound, the
     * flashes and stage 5; its resting contacts become persistent contacts. Returns what the collision itself hit.
     */
    private Struck noteImpacts(Collision collision, ContactCluster cluster, double[] impact,
                               NormalImpulses.Result result) {
        Struck own = collision.contact().struck();
        heard.clear();
        List<Ball> balls = cluster.balls();
        for (int i = 0; i < cluster.rows().size(); i++) {
            ClusterRow row = cluster.rows().get(i);
            Ball ball = balls.get(row.ball());
            double change = result.compression()[i];
            if (change <= 0) {
                continue;
            }
            if (change <= impact[i]) {
                rest(ball, row, balls);
                continue;
            }
            Struck struck = row.other().struck(balls);
            GizmoBase target = struck instanceof TriggerSource.OfGizmo gizmo ? step.view.gizmo(gizmo.gizmo()) : null;
            if (target != null) {
                target.markTriggered(step.now());
            }
            if (heard.firstFrom(struck)) {
                GizmoKind kind = target == null ? null : target.kind();
                step.actions.recordHit(ball, struck, kind, change);
                if (struck instanceof TriggerSource source && !struck.equals(own)) {
                    step.alsoHit.add(source);
                }
            }
        }
        return own;
    }

    /**
     * A resting contact of the solve becomes a persistent contact, and the velocities stay as the solve gave them:
     * they close on nothing. Projected once more as if a supporting ball stood still, a ball resting on one the solve
     * set moving would be sent back into what it was pressed against, and the cluster met again at no time apart (a
     * row of balls between a wall and a square, pushed along: 400 collisions a tick to the cap).
     */
    private static void rest(Ball ball, ClusterRow row, List<Ball> balls) {
        if (row.other() instanceof ClusterRow.Other.Still still) {
            Contacts.attach(ball, still.ref());
        } else if (row.other() instanceof ClusterRow.Other.InCluster in) {
            Ball other = balls.get(in.index());
            holdOn(ball, other);
            holdOn(other, ball);
        }
    }

    private static void holdOn(Ball ball, Ball support) {
        if (!ball.isAsleep() && Contacts.supports(support, ball)) {
            Contacts.attach(ball, new ContactRef.OnBall(support.name()));
        }
    }
}
