package gizmoball.model;

import gizmoball.model.gizmo.Absorber;
import gizmoball.model.gizmo.BallHolder;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.gizmo.PlayState;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.gizmo.SwitchedCell;
import gizmoball.model.loop.Arena;
import gizmoball.model.loop.Ball;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import physics.Vect;

/**
 * The editing operations on gizmos and balls (the {@link Board} methods of the same names say what each does).
 * Each checks the change first, on a copy of the gizmo where it changes one, through the {@link PlacementRules},
 * and throws {@link BoardEditException} before it has changed anything; the board then tells its observers.
 */
final class Edits {
    private final Registry registry;
    private final PlacementRules rules;
    private final Wiring wiring;
    private final Play play;

    Edits(Registry registry, PlacementRules rules, Wiring wiring, Play play) {
        this.registry = registry;
        this.rules = rules;
        this.wiring = wiring;
        this.play = play;
    }

    void addGizmo(GizmoKind kind, String name, int x, int y) {
        if (kind == null || kind.sizedByCorners()) {
            throw new BoardEditException("cannot add " + name + ": addGizmo takes a bumper or flipper kind, not "
                    + kind + " (absorbers are added with their corners)");
        }
        rules.requireFreshName(name);
        GizmoBase candidate = kind.create(name, x, y);
        refuseIfPresent(rules.problemFor(candidate, null));
        registry.insert(candidate);
    }

    void addAbsorber(String name, int x1, int y1, int x2, int y2) {
        rules.requireFreshName(name);
        if (x2 <= x1 || y2 <= y1) {
            throw new BoardEditException("absorber " + name + " from (" + x1 + "," + y1 + ") to (" + x2 + "," + y2
                    + ") must be at least one cell wide and high ((x2, y2) is the exclusive bottom-right corner)");
        }
        Absorber candidate = new Absorber(name, x1, y1, x2 - x1, y2 - y1);
        refuseIfPresent(rules.problemFor(candidate, null));
        registry.insert(candidate);
        play.captureFreeBallsIn(candidate);
    }

    void addBall(String name, double x, double y, double vx, double vy) {
        placeBall(name, x, y, vx, vy, false);
    }

    List<String> addBallOverlappingBalls(String name, double x, double y, double vx, double vy) {
        Ball ball = placeBall(name, x, y, vx, vy, true);
        List<String> overlapped = ball.isCaptured() ? List.of() : registry.balls().stream()
                .filter(other -> other != ball && !other.isCaptured()
                        && Overlaps.balls(other.position(), ball.position()))
                .map(Ball::name)
                .toList();
        overlapped.forEach(other -> registry.passThrough(name, other));
        return overlapped;
    }

    private Ball placeBall(String name, double x, double y, double vx, double vy, boolean ballsMayOverlap) {
        rules.requireFreshName(name);
        if (!Double.isFinite(vx) || !Double.isFinite(vy)) {
            throw new BoardEditException("ball " + name + ": velocity (" + vx + "," + vy + ") must be finite");
        }
        Vect position = new Vect(requireFinite(x, name), requireFinite(y, name));
        GizmoBase captor = rules.captorOfPlacedBall(name, position, Set.of(), ballsMayOverlap);
        Ball ball = new Ball(name, position, Vect.ZERO);
        ball.setVelocity(new Vect(vx, vy));
        registry.add(ball);
        if (captor != null) {
            play.take(ball, captor);
        }
        return ball;
    }

    void setFlipperState(String flipper, double degrees, boolean active) {
        restore(flipper, new PlayState.Swung(degrees, active), flipper + " is not a flipper",
                "flipper " + flipper + " at " + degrees + " degrees");
    }

    /**
     * Puts the gizmo as play left it, if it {@link GizmoBase#canBe} so ({@code onlyFor} refuses any other) with no
     * problem, and no free ball is inside it there ({@code at} names it so in the refusal).
     */
    private void restore(String name, PlayState state, String onlyFor, String at) {
        GizmoBase target = registry.requireGizmo(name);
        if (!target.canBe(state)) {
            throw new BoardEditException(onlyFor);
        }
        refuseIfPresent(target.restoreProblem(state));
        GizmoBase candidate = target.copy();
        candidate.restore(state);
        refuseIfPresent(rules.ballOverlap(candidate).map(ball -> PlacementRules.wouldOverlap(at, "ball", ball)));
        target.restore(state);
    }

    void rotate(String gizmo) {
        GizmoBase target = registry.requireGizmo(gizmo);
        if (target.kind().rotates()) {
            GizmoBase candidate = target.copy();
            candidate.rotateClockwise();
            refuseIfPresent(rules.ballOverlap(candidate).map(ball -> "rotating " + gizmo + " would make it overlap ball "
                    + ball));
            target.rotateClockwise();
        }
    }

    void delete(String name) {
        GizmoBase gizmo = registry.gizmo(name);
        Ball ball = registry.ball(name);
        if (gizmo != null) {
            if (gizmo.setting() instanceof Setting.Pair) {   // a portal: its pair is left without one
                gizmo.hold(new Setting.Pair(Optional.empty()), registry::gizmo);
            }
            registry.remove(gizmo);
            wiring.forget(name);
        } else if (ball != null) {
            registry.remove(ball);
        } else {
            throw new BoardEditException("cannot delete " + name + ": no gizmo or ball named " + name);
        }
    }

    void moveGizmo(String gizmo, int x, int y) {
        GizmoBase target = registry.requireGizmo(gizmo);
        GizmoBase candidate = target.copy();
        candidate.moveTo(x, y);
        refuseIfPresent(rules.problemFor(candidate, gizmo));
        registry.move(target, x, y);
        if (target instanceof BallHolder holder) {
            holder.held().forEach(held -> registry.ball(held).capture(holder.holdingPosition(Arena.BALL_RADIUS)));
            play.captureFreeBallsIn(target);
        }
    }

    void moveGroup(Collection<String> names, double dx, double dy) {
        Set<String> group = new LinkedHashSet<>(names);
        List<GizmoBase> gizmos = new ArrayList<>();
        List<Ball> balls = new ArrayList<>();
        for (String name : group) {
            GizmoBase gizmo = registry.gizmo(name);
            Ball ball = registry.ball(name);
            if (gizmo != null) {
                gizmos.add(gizmo);
            } else if (ball != null) {
                balls.add(ball);
            } else {
                throw new BoardEditException("cannot move " + name + ": no gizmo or ball named " + name);
            }
        }
        if (!Double.isFinite(dx) || !Double.isFinite(dy)) {
            throw new BoardEditException("a move by (" + dx + "," + dy + ") is not finite");
        }
        if (!gizmos.isEmpty() && (dx != Math.rint(dx) || dy != Math.rint(dy))) {
            throw new BoardEditException("gizmos move by whole cells, not by (" + dx + "," + dy + ")");
        }
        int cx = (int) dx;
        int cy = (int) dy;
        // A ball an absorber of the group holds goes with it; so do the balls any moved absorber holds.
        Set<String> heldInGroup = new HashSet<>();
        gizmos.forEach(gizmo -> heldInGroup.addAll(gizmo.held()));
        List<Ball> loose = balls.stream().filter(b -> !heldInGroup.contains(b.name())).toList();
        Map<Ball, GizmoBase> captors = new HashMap<>();
        // The group moves as one: checked with its own gizmos out of the grid, so that none is in another's way.
        gizmos.forEach(registry.index()::remove);
        try {
            for (GizmoBase gizmo : gizmos) {
                GizmoBase candidate = gizmo.copy();
                candidate.moveTo(gizmo.x() + cx, gizmo.y() + cy);
                refuseIfPresent(rules.problemFor(candidate, null, group));
            }
            for (Ball ball : loose) {
                Vect position = new Vect(requireFinite(ball.position().x() + dx, ball.name()),
                        requireFinite(ball.position().y() + dy, ball.name()));
                GizmoBase captor = rules.captorOfPlacedBall(ball.name(), position, group, false);
                if (captor != null) {
                    captors.put(ball, captor);
                }
            }
        } catch (BoardEditException refused) {
            gizmos.forEach(registry.index()::put);
            throw refused;
        }
        for (GizmoBase gizmo : gizmos) {
            gizmo.moveTo(gizmo.x() + cx, gizmo.y() + cy);
        }
        gizmos.forEach(registry.index()::put);
        for (Ball ball : loose) {
            Vect position = ball.position().plus(new Vect(dx, dy));
            if (ball.isCaptured()) {
                registry.releaseFromAbsorber(ball);
                ball.release(position, Vect.ZERO);
            } else {
                ball.moveTo(position);
            }
        }
        for (GizmoBase gizmo : gizmos) {
            if (gizmo instanceof BallHolder holder) {
                holder.held().forEach(held -> registry.ball(held).capture(holder.holdingPosition(Arena.BALL_RADIUS)));
            }
        }
        captors.forEach(play::take);
        gizmos.stream().filter(g -> g instanceof BallHolder).forEach(play::captureFreeBallsIn);
    }

    void resizeAbsorber(String name, int x1, int y1, int x2, int y2) {
        if (!(registry.requireGizmo(name) instanceof Absorber target)) {
            throw new BoardEditException(name + " is not an absorber: only an absorber can be resized");
        }
        if (x2 <= x1 || y2 <= y1) {
            throw new BoardEditException("absorber " + name + " from (" + x1 + "," + y1 + ") to (" + x2 + "," + y2
                    + ") must be at least one cell wide and high ((x2, y2) is the exclusive bottom-right corner)");
        }
        Absorber candidate = target.resized(x1, y1, x2 - x1, y2 - y1);
        refuseIfPresent(rules.problemFor(candidate, name));
        registry.replace(target, candidate);
        candidate.held().forEach(held -> registry.ball(held).capture(candidate.holdingPosition(Arena.BALL_RADIUS)));
        play.captureFreeBallsIn(candidate);
    }

    void moveBall(String ball, double x, double y) {
        Ball target = registry.ball(ball);
        if (target == null) {
            throw new BoardEditException("cannot move " + ball + ": no ball named " + ball);
        }
        Vect position = new Vect(requireFinite(x, ball), requireFinite(y, ball));
        GizmoBase captor = rules.captorOfPlacedBall(ball, position, ball, false);
        if (target.isCaptured()) {
            registry.releaseFromAbsorber(target);
            target.release(position, Vect.ZERO);
        } else {
            target.moveTo(position);
        }
        if (captor != null) {
            play.take(target, captor);
        }
    }

    boolean setBallVelocity(String ball, double vx, double vy) {
        Ball target = registry.ball(ball);
        if (target == null) {
            throw new BoardEditException("cannot set the velocity of " + ball + ": no ball named " + ball);
        }
        if (!Double.isFinite(vx) || !Double.isFinite(vy)) {
            throw new BoardEditException("ball " + ball + ": velocity (" + vx + ", " + vy + ") is not finite");
        }
        Vect velocity = new Vect(vx, vy);
        if (target.isCaptured()) {
            if (!velocity.equals(Vect.ZERO)) {
                throw new BoardEditException(ball + " is held by an absorber: it cannot be given a velocity");
            }
            return false;
        }
        target.setVelocity(velocity);
        return true;
    }

    void setColour(String gizmo, Optional<Rgb> colour) {
        if (colour == null) {
            throw new BoardEditException("colour of " + gizmo + " must be a colour or empty, not null");
        }
        registry.requireGizmo(gizmo).setColour(colour);
    }

    /**
     * Gives a gizmo a setting of the record it holds, if the setting's own check finds no problem (the one check of
     * every kind's value, {@link Setting#problem}).
     */
    void set(String gizmo, Setting setting) {
        GizmoBase target = registry.requireGizmo(gizmo);
        if (setting == null || target.setting().getClass() != setting.getClass()) {
            throw new BoardEditException((setting == null ? "a setting must not be null" : setting.onlyFor()) + ": "
                    + gizmo + " is " + target.kind().withArticle());
        }
        refuseIfPresent(setting.problem(gizmo, new Setting.Board() {
            public Gizmo gizmo(String name) {
                return (Gizmo) registry.requireGizmo(name);
            }

            public double maxSpeed() {
                return Arena.MAX_SPEED;
            }
        }));
        target.hold(setting, registry::gizmo);
    }

    void setSpinnerState(String gizmo, double radians, boolean running) {
        restore(gizmo, new PlayState.Turned(radians, running), "only a spinner has an angle: " + gizmo + " is "
                + registry.requireGizmo(gizmo).kind().withArticle(), "spinner " + gizmo + " at " + radians + " radians");
    }

    void setCellOpen(String name) {
        if (!(registry.requireGizmo(name) instanceof SwitchedCell cell)) {
            throw new BoardEditException("only a gate is open or a drop target down: " + name + " is "
                    + registry.requireGizmo(name).kind().withArticle());
        }
        play.switchCell(cell, false);
    }

    private static double requireFinite(double coordinate, String ball) {
        if (!Double.isFinite(coordinate)) {
            throw new BoardEditException("ball " + ball + ": position " + coordinate + " is not a finite number");
        }
        return coordinate;
    }

    private static void refuseIfPresent(Optional<String> problem) {
        if (problem.isPresent()) {
            throw new BoardEditException(problem.get());
        }
    }
}
