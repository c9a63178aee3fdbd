package gizmoball.fuzz;

import gizmoball.model.Board;
import gizmoball.model.gizmo.Absorber;
import gizmoball.model.gizmo.Accelerator;
import gizmoball.model.gizmo.Sink;
import gizmoball.model.gizmo.Spinner;
import gizmoball.model.gizmo.Flipper;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.PortalView;
import gizmoball.model.gizmo.SpawnerView;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.PlayEvent;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * Checks a board in play after every tick with geometry of its own ({@link Bodies}, {@link Solid}): no NaN, no free
 * ball outside the board, inside a gizmo (a flipper at its current angle) or inside another free ball by more than
 * {@link #TOLERANCE}; on a board without gravity, friction, flippers and absorbers no kinetic energy gained beyond
 * rounding; and no ball frozen in free flight (free, awake, with nothing within its reach in the tick, moving, yet
 * exactly where it was a tick before). It also notes balls hovering: kept still though moving or falling, near things
 * but touching none (not a rule of issue 20; see {@link Violation.Kind#HOVERING}). It checks play at 1/60 s.
 *
 * <p>It follows the balls that come and go (issue 39): a ball appears only by a spawner, at its mouth with its velocity
 * (where the spawn was asked for in the tick, at the tick's end: exactly there; by a key between ticks, exactly there
 * when {@link #keysPressed} looks), and the report after it appeared says so; a ball leaves only by a sink that it
 * touched, in a tick whose report says so; and a ball that went through a portal came out where its pair's frame says
 * (docs/design.md, "Portals"), reckoned here from the portals' cells and rotations.
 *
 * <p>Play moves no gizmo but a flipper's bar, so the other gizmos are read once, when the checker is made, and filed
 * by cell; the flippers and the balls are read after every tick. Balls are read through {@link Board#balls()}, gizmos
 * through the kinds' read-only accessors.
 */
public final class TickChecker {
    /** L: the penetration the issue allows (the loop's own invariant tolerance, stated here again on purpose). */
    public static final double TOLERANCE = 1e-6;
    /** Relative: kinetic energy may grow by rounding only. */
    public static final double ENERGY_ROUNDING = 1e-9;
    /** L/s: a velocity smaller than this is no claim to be moving (in a tick of 1/60 s it moves a ball 1.7e-8 L). */
    static final double STILL_SPEED = 1e-6;
    /** L: a ball farther than this from everything touches nothing. */
    static final double TOUCH_GAP = 1e-6;
    /** s: the tick the fuzz and the reproductions play at. */
    static final double DT = Board.DEFAULT_TICK;

    private static final double R = Board.BALL_RADIUS;
    /** L/s: the speed an absorber fires a ball at (docs/rules.md, "Gizmos"), stated here again on purpose. */
    private static final double LAUNCH_SPEED = 50;
    /** L/s: no ball is faster (docs/rules.md, "Gizmos"), stated here again on purpose. */
    private static final double MAX_SPEED = 200;
    /** The most balls a spawner fills a board to (docs/board-files.md, "Board files"), stated here again on purpose. */
    static final int MOST_BALLS = 200;
    /** L: where the spawner puts a ball and where a portal's pair sends it are reckoned exactly; rounding only. */
    static final double PLACE_ROUNDING = 1e-9;
    private static final int SIZE = Board.SIZE;

    private record Body(String name, Solid solid) {
    }

    /** A ball as the last check saw it: where, how fast, and how far from the nearest thing (exact below 2e-6 L). */
    private record BallAt(double x, double y, double vx, double vy, boolean captured, double gap) {
    }

    /** The still bodies whose box, widened by a ball's radius and a margin, meets each cell. */
    private final List<List<Body>> cells = new ArrayList<>();
    private final List<Body> still = new ArrayList<>();
    private final List<Flipper> flippers = new ArrayList<>();
    private final List<Spinner> spinners = new ArrayList<>();
    /** Gates and drop targets: their cells are bodies only while they are there (read after every tick). */
    private final List<Gizmo> switching = new ArrayList<>();
    /** The boxes flippers and spinners turn in: nothing of either is ever outside its 2 x 2 box. */
    private final List<Body> flipperBoxes = new ArrayList<>();
    private final boolean energyKept;
    private final double gravity;
    private final double mu;
    private final double mu2;
    private final Map<String, BallAt> before = new HashMap<>();
    private final Map<String, Gizmo> byName = new HashMap<>();
    /** The balls on the board when it was last seen (at the last check, or since by {@link #keysPressed}). */
    private final Set<String> known = new HashSet<>();
    /**
     * Balls seen appearing whose spawn no report has named yet, with the tick after which they were seen: the report
     * of the next tick must (a spawn asked for in a tick happens at its end, after its report).
     */
    private final Map<String, Integer> unreported = new LinkedHashMap<>();
    /** The absorbers that fired in the tick being checked. */
    private List<Gizmo> fired = List.of();
    private double kineticBefore;

    /** Reads the board as it is now (before the first tick, or at any tick the checking starts from). */
    public TickChecker(Board board) {
        this(board.gizmos(), board.gravity(), board.mu(), board.mu2(), board.balls());
    }

    /** A board of these gizmos and constants whose balls are now {@code balls}. */
    TickChecker(List<? extends Gizmo> gizmos, double gravity, double mu, double mu2, List<BallView> balls) {
        for (int i = 0; i < SIZE * SIZE; i++) {
            cells.add(new ArrayList<>());
        }
        boolean movers = false;
        for (Gizmo gizmo : gizmos) {
            byName.put(gizmo.name(), gizmo);
            if (gizmo instanceof Flipper flipper) {
                flippers.add(flipper);
                flipperBoxes.add(new Body(flipper.name(), Bodies.box(flipper)));
                movers = true;
                continue;
            }
            if (gizmo instanceof Spinner spinner) {
                spinners.add(spinner);
                flipperBoxes.add(new Body(spinner.name(), Bodies.box(spinner)));
                movers = true;
                continue;
            }
            if (Bodies.switches(gizmo)) {
                switching.add(gizmo);
                continue;
            }
            // What changes the balls' energy other than the contract's loss: capture, removal, a boost.
            movers |= gizmo instanceof Absorber || gizmo instanceof Sink || gizmo instanceof Accelerator
                    || gizmo instanceof SpawnerView;
            Body body = new Body(gizmo.name(), Bodies.of(gizmo));
            still.add(body);
            file(body);
        }
        this.gravity = gravity;
        this.mu = mu;
        this.mu2 = mu2;
        energyKept = !movers && gravity == 0 && mu == 0 && mu2 == 0;
        // No positions yet: a ball can only be seen frozen over a tick it was checked before.
        kineticBefore = kinetic(balls.stream().filter(b -> !b.isCaptured()).toList());
        balls.forEach(ball -> known.add(ball.name()));
    }

    /** True when the board keeps kinetic energy (no gravity, friction, flippers or absorbers): it is checked. */
    public boolean checksEnergy() {
        return energyKept;
    }

    private void file(Body body) {
        double[] box = body.solid().bounds();
        double reach = R + 2 * TOUCH_GAP;
        int x0 = clampCell(box[0] - reach);
        int y0 = clampCell(box[1] - reach);
        int x1 = clampCell(box[2] + reach);
        int y1 = clampCell(box[3] + reach);
        for (int cy = y0; cy <= y1; cy++) {
            for (int cx = x0; cx <= x1; cx++) {
                cells.get(cy * SIZE + cx).add(body);
            }
        }
    }

    private static int clampCell(double coordinate) {
        return (int) Math.max(0, Math.min(SIZE - 1, Math.floor(coordinate)));
    }

    /** The violations of the board as it is now, after tick {@code tick}; the board is then remembered for the next. */
    public List<Violation> check(Board board, int tick) {
        return check(board.balls(), tick, board.lastTick() == null ? List.of() : board.lastTick().events());
    }

    /** As {@link #check(Board, int)} for the board's balls as they are now, after a tick that reported nothing. */
    List<Violation> check(List<BallView> balls, int tick) {
        return check(balls, tick, List.of());
    }

    /**
     * The keys due before tick {@code tick} have been pressed: a ball a spawner added must be at its mouth with its
     * velocity, and the tick's report must say so; it is then followed as if it had been there after the last tick.
     * (Other effects of keys, a flipper starting to swing or an absorber firing, show in the tick itself.)
     */
    public List<Violation> keysPressed(Board board, int tick) {
        List<Violation> found = new ArrayList<>();
        for (BallView ball : board.balls()) {
            if (known.add(ball.name())) {
                checkAtAMouth(ball, tick, found);
                unreported.put(ball.name(), tick - 1);
                before.put(ball.name(), new BallAt(ball.position().x(), ball.position().y(), ball.velocity().x(),
                        ball.velocity().y(), false, 0));   // it touches its spawner
            }
        }
        kineticBefore = kinetic(board.balls().stream().filter(b -> !b.isCaptured()).toList());
        return found;
    }

    /**
     * As {@link #check(Board, int)}; {@code events}: what the tick reported (absorbers that fired, balls spawned, sunk
     * and sent through portals). A fired ball may be caught again in the same tick, held at both ends of it, and its
     * way out and back is seen nowhere else.
     */
    List<Violation> check(List<BallView> balls, int tick, List<PlayEvent> events) {
        fired = new ArrayList<>();
        for (PlayEvent event : events) {
            if (event instanceof PlayEvent.Fired shot && byName.get(shot.absorber()) != null) {
                fired.add(byName.get(shot.absorber()));
            }
        }
        List<Violation> found = new ArrayList<>();
        checkComingAndGoing(balls, tick, events, found);
        List<BallView> free = new ArrayList<>();
        for (BallView ball : balls) {
            if (!finite(ball)) {
                found.add(new Violation(Violation.Kind.NOT_A_NUMBER, tick, ball.name(), Double.NaN, ball.toString()));
            } else if (!ball.isCaptured()) {
                free.add(ball);
            }
        }
        List<Body> moving = new ArrayList<>();
        for (Flipper flipper : flippers) {
            moving.add(new Body(flipper.name(), Bodies.flipper(flipper)));
        }
        for (Spinner spinner : spinners) {
            moving.add(new Body(spinner.name(), Bodies.spinner(spinner)));
        }
        for (Gizmo cell : switching) {
            if (Bodies.present(cell)) {
                moving.add(new Body(cell.name(), Bodies.of(cell)));
            }
        }
        for (PlayEvent event : events) {
            if (event instanceof PlayEvent.Teleported jump) {
                checkJump(jump, tick, found);
            }
        }
        double[] gaps = new double[free.size()];
        for (int i = 0; i < free.size(); i++) {
            gaps[i] = checkAgainstBoard(free.get(i), moving, tick, found);
        }
        checkPairs(free, gaps, tick, found);
        for (int i = 0; i < free.size(); i++) {
            checkStill(free.get(i), gaps[i], free, tick, found);
        }
        if (energyKept) {
            double kinetic = kinetic(free);
            if (kinetic > kineticBefore * (1 + ENERGY_ROUNDING) + Double.MIN_NORMAL) {
                found.add(new Violation(Violation.Kind.ENERGY_GAINED, tick, "all",
                        kineticBefore == 0 ? Double.POSITIVE_INFINITY : kinetic / kineticBefore - 1,
                        "kinetic energy " + kineticBefore + " -> " + kinetic));
            }
        }
        Map<String, Double> gapOf = new HashMap<>();
        for (int i = 0; i < free.size(); i++) {
            gapOf.put(free.get(i).name(), gaps[i]);
        }
        remember(balls, gapOf);
        return found;
    }

    /**
     * Balls that appeared since the last check were spawned: at the tick's end (exactly at a spawner's mouth with its
     * velocity, named by the next report), or before it began (named by this tick's report; by a key,
     * {@link #keysPressed} saw it, or by an order that waited, no farther from a mouth than a ball goes in a tick).
     * Balls that left were taken by a sink they touched, in this tick. The board never holds more than
     * {@link #MOST_BALLS} once a spawner has added one.
     */
    private void checkComingAndGoing(List<BallView> balls, int tick, List<PlayEvent> events, List<Violation> found) {
        Set<String> present = new HashSet<>();
        for (BallView ball : balls) {
            present.add(ball.name());
        }
        Set<String> sunk = new HashSet<>();
        for (PlayEvent event : events) {
            if (event instanceof PlayEvent.Spawned spawned) {
                String ball = spawned.ball();
                if (!(byName.get(spawned.spawner()) instanceof SpawnerView spawner)) {
                    found.add(new Violation(Violation.Kind.APPEARED, tick, ball, Double.NaN,
                            "spawned by " + spawned.spawner() + ", which is no spawner of the board"));
                } else if (unreported.remove(ball) == null) {
                    BallView now = balls.stream().filter(b -> b.name().equals(ball)).findFirst().orElse(null);
                    if (now == null && !known.contains(ball)) {
                        found.add(new Violation(Violation.Kind.APPEARED, tick, ball, Double.NaN,
                                "reported spawned by " + spawner.name() + " but never seen"));
                    } else if (now != null && known.add(ball)) {
                        // spawned when the tick began (an order that waited): at most a tick's way from the mouth
                        double[] mouth = mouth(spawner);
                        double off = Math.hypot(now.position().x() - mouth[0], now.position().y() - mouth[1]);
                        if (off > MAX_SPEED * DT + TOLERANCE) {
                            found.add(new Violation(Violation.Kind.APPEARED, tick, ball, off,
                                    "spawned by " + spawner.name() + " as the tick began, yet farther from its mouth"));
                        }
                        before.put(ball, new BallAt(now.position().x(), now.position().y(), now.velocity().x(),
                                now.velocity().y(), false, 0));
                    } else {
                        found.add(new Violation(Violation.Kind.APPEARED, tick, ball, Double.NaN,
                                "reported spawned by " + spawner.name() + " though it was there before"));
                    }
                }
            } else if (event instanceof PlayEvent.Sunk taken) {
                sunk.add(taken.ball());
                checkSunk(taken, present, tick, found);
            }
        }
        for (Map.Entry<String, Integer> waiting : unreported.entrySet()) {
            found.add(new Violation(Violation.Kind.APPEARED, tick, waiting.getKey(), Double.NaN,
                    "appeared after tick " + waiting.getValue() + " and the next report did not name its spawn"));
        }
        unreported.clear();
        for (BallView ball : balls) {
            if (!known.contains(ball.name())) {
                checkAtAMouth(ball, tick, found);
                unreported.put(ball.name(), tick);
            }
        }
        for (String name : known) {
            if (!present.contains(name) && !sunk.contains(name)) {
                found.add(new Violation(Violation.Kind.VANISHED, tick, name, Double.NaN, "left the board, no sink took it"));
            }
        }
        if (balls.size() > MOST_BALLS && balls.size() > known.size()) {
            found.add(new Violation(Violation.Kind.APPEARED, tick, "all", balls.size(),
                    balls.size() + " balls, more than a spawner fills a board to"));
        }
    }

    /** A ball just spawned: exactly at the mouth of some spawner, with that spawner's velocity. */
    private void checkAtAMouth(BallView ball, int tick, List<Violation> found) {
        double nearest = Double.POSITIVE_INFINITY;
        for (Gizmo gizmo : byName.values()) {
            if (gizmo instanceof SpawnerView spawner) {
                double[] mouth = mouth(spawner);
                double off = Math.hypot(ball.position().x() - mouth[0], ball.position().y() - mouth[1]);
                boolean itsVelocity = ball.velocity().x() == spawner.velocity().x()
                        && ball.velocity().y() == spawner.velocity().y();
                if (off <= PLACE_ROUNDING && itsVelocity) {
                    return;
                }
                nearest = Math.min(nearest, off);
            }
        }
        found.add(new Violation(Violation.Kind.APPEARED, tick, ball.name(), nearest, String.format(Locale.ROOT,
                "appeared at (%s, %s) with (%s, %s), at no spawner's mouth with its velocity", ball.position().x(),
                ball.position().y(), ball.velocity().x(), ball.velocity().y())));
    }

    /**
     * A spawner's mouth (docs/board-files.md, "Board files"): a ball's centre touching the middle of the side it faces,
     * up unturned, then right, down, left with each quarter turn.
     */
    private static double[] mouth(Gizmo spawner) {
        double[] n = facing(spawner.rotation());
        double out = 0.5 + R;
        return new double[] {spawner.x() + 0.5 + n[0] * out, spawner.y() + 0.5 + n[1] * out};
    }

    /** The outward normal of the side a spawner or a portal faces after {@code quarterTurns} clockwise. */
    private static double[] facing(int quarterTurns) {
        return switch (Math.floorMod(quarterTurns, 4)) {
            case 0 -> new double[] {0, -1};
            case 1 -> new double[] {1, 0};
            case 2 -> new double[] {0, 1};
            default -> new double[] {-1, 0};
        };
    }

    /** The ball was taken by the sink: it has left the board, and it touched the sink when it was taken. */
    private void checkSunk(PlayEvent.Sunk taken, Set<String> present, int tick, List<Violation> found) {
        if (present.contains(taken.ball())) {
            found.add(new Violation(Violation.Kind.VANISHED, tick, taken.ball(), Double.NaN,
                    "reported taken by " + taken.sink() + " yet still on the board"));
        }
        Gizmo sink = byName.get(taken.sink());
        if (!(sink instanceof Sink)) {
            found.add(new Violation(Violation.Kind.VANISHED, tick, taken.ball(), Double.NaN,
                    "taken by " + taken.sink() + ", which is no sink of the board"));
            return;
        }
        double gap = Bodies.of(sink).signedDistance(taken.at().x(), taken.at().y()) - R;
        if (Math.abs(gap) > TOLERANCE) {
            found.add(new Violation(Violation.Kind.VANISHED, tick, taken.ball(), gap,
                    "taken by " + taken.sink() + " from (" + taken.at().x() + ", " + taken.at().y() + "), not touching it"));
        }
    }

    /**
     * A ball went through a portal: the portal has the exit as its pair; the ball touched its mouth from outside
     * (r out along its facing n, at most half the mouth along it); and it came out where the pair's frame puts it
     * (docs/design.md, "Portals": meeting A's mouth at r n_A + t e_A, it leaves at r n_B - t e_B, e the facing turned a
     * quarter clockwise), on a spot clear of the walls and of every gizmo that stays where it is (the loop looked at
     * the spot when the ball met the mouth; gates, flippers and spinners may have moved since).
     */
    private void checkJump(PlayEvent.Teleported jump, int tick, List<Violation> found) {
        Gizmo entry = byName.get(jump.portal());
        Gizmo exit = byName.get(jump.exit());
        if (!(entry instanceof PortalView a) || !(exit instanceof PortalView b) || !a.pair().equals(Optional.of(b.name()))) {
            found.add(new Violation(Violation.Kind.JUMPED, tick, jump.ball(), Double.NaN,
                    "through " + jump.portal() + " to " + jump.exit() + ", which are no pair of portals"));
            return;
        }
        double[] nA = facing(a.rotation());
        double[] nB = facing(b.rotation());
        double dx = jump.at().x() - (a.x() + 0.5 + nA[0] / 2);
        double dy = jump.at().y() - (a.y() + 0.5 + nA[1] / 2);
        double out = dx * nA[0] + dy * nA[1];
        double along = -dx * nA[1] + dy * nA[0];   // e = (-n_y, n_x)
        if (Math.abs(out - R) > TOLERANCE || Math.abs(along) > 0.5 + TOLERANCE) {
            found.add(new Violation(Violation.Kind.JUMPED, tick, jump.ball(), Math.abs(out - R), String.format(
                    Locale.ROOT, "entered %s from (%s, %s), %s out from its mouth and %s along it, not touching it",
                    a.name(), jump.at().x(), jump.at().y(), out, along)));
        }
        double x = b.x() + 0.5 + nB[0] * (0.5 + R) + along * nB[1];
        double y = b.y() + 0.5 + nB[1] * (0.5 + R) - along * nB[0];
        double off = Math.hypot(jump.out().x() - x, jump.out().y() - y);
        if (off > PLACE_ROUNDING + Math.abs(out - R)) {
            found.add(new Violation(Violation.Kind.JUMPED, tick, jump.ball(), off, String.format(Locale.ROOT,
                    "left %s at (%s, %s), where its frame says (%s, %s)", b.name(), jump.out().x(), jump.out().y(), x, y)));
        }
        double gap = Math.min(Math.min(x - R, SIZE - R - x), Math.min(y - R, SIZE - R - y));
        String in = "the walls";
        for (Body body : cells.get(clampCell(y) * SIZE + clampCell(x))) {
            double g = body.solid().signedDistance(x, y) - R;
            if (g < gap) {
                gap = g;
                in = body.name();
            }
        }
        if (gap < -TOLERANCE) {
            found.add(new Violation(Violation.Kind.JUMPED, tick, jump.ball(), -gap, "came out of " + b.name()
                    + " into " + in));
        }
    }

    private static boolean finite(BallView ball) {
        return Double.isFinite(ball.position().x()) && Double.isFinite(ball.position().y())
                && Double.isFinite(ball.velocity().x()) && Double.isFinite(ball.velocity().y());
    }

    /** Walls, still gizmos and flippers; returns the ball's gap to the nearest of them (negative: inside). */
    private double checkAgainstBoard(BallView ball, List<Body> moving, int tick, List<Violation> found) {
        double x = ball.position().x();
        double y = ball.position().y();
        double wallGap = Math.min(Math.min(x - R, SIZE - R - x), Math.min(y - R, SIZE - R - y));
        if (wallGap < -TOLERANCE) {
            found.add(new Violation(Violation.Kind.ESCAPED, tick, ball.name(), -wallGap,
                    "centre (" + x + ", " + y + ")"));
        }
        double gap = wallGap;
        for (Body body : cells.get(clampCell(y) * SIZE + clampCell(x))) {
            gap = Math.min(gap, against(ball, body, tick, found));
        }
        for (Body body : moving) {
            double[] box = body.solid().bounds();
            if (x > box[0] - R - TOUCH_GAP && x < box[2] + R + TOUCH_GAP && y > box[1] - R - TOUCH_GAP
                    && y < box[3] + R + TOUCH_GAP) {
                gap = Math.min(gap, against(ball, body, tick, found));
            }
        }
        return gap;
    }

    private static double against(BallView ball, Body body, int tick, List<Violation> found) {
        double gap = body.solid().signedDistance(ball.position().x(), ball.position().y()) - R;
        if (gap < -TOLERANCE) {
            found.add(new Violation(Violation.Kind.INSIDE_GIZMO, tick, ball.name(), -gap, "inside " + body.name()));
        }
        return gap;
    }

    private static void checkPairs(List<BallView> free, double[] gaps, int tick, List<Violation> found) {
        for (int i = 0; i < free.size(); i++) {
            BallView a = free.get(i);
            for (int j = i + 1; j < free.size(); j++) {
                BallView b = free.get(j);
                double dx = a.position().x() - b.position().x();
                double dy = a.position().y() - b.position().y();
                if (Math.abs(dx) > 2 * R + TOUCH_GAP || Math.abs(dy) > 2 * R + TOUCH_GAP) {
                    continue;
                }
                double gap = Math.hypot(dx, dy) - 2 * R;
                gaps[i] = Math.min(gaps[i], gap);
                gaps[j] = Math.min(gaps[j], gap);
                if (gap < -TOLERANCE) {
                    found.add(new Violation(Violation.Kind.INSIDE_BALL, tick, a.name(), -gap, "inside " + b.name()));
                }
            }
        }
    }

    /**
     * A free, awake ball that touched nothing at the start of the tick (more than {@link #TOUCH_GAP} from everything)
     * and does not at its end, whose velocity after the tick's friction and gravity would move it, yet is exactly
     * where it was. Frozen: nothing was within its reach in the tick (what it would travel, and what any other ball
     * did), so it was in free flight and the loop stopped it in mid-air. Hovering (noted): something was near enough
     * to have met it, yet it did not move, held apart from what it does not touch.
     */
    private void checkStill(BallView ball, double gap, List<BallView> free, int tick, List<Violation> found) {
        BallAt last = before.get(ball.name());
        if (last == null || last.captured() || ball.isAsleep() || last.gap() <= TOUCH_GAP || gap <= TOUCH_GAP
                || ball.position().x() != last.x() || ball.position().y() != last.y()) {
            return;
        }
        // Stage 1 of the tick (docs/rules.md, "The tick"): v (1 - mu dt - mu2 |v| dt) + g dt, gravity along +y;
        // friction that would take more than the whole velocity stops the ball instead of turning it round.
        double speedBefore = Math.hypot(last.vx(), last.vy());
        double keep = Math.max(0, 1 - mu * DT - mu2 * speedBefore * DT);
        double speed = Math.hypot(last.vx() * keep, last.vy() * keep + gravity * DT);
        if (speed <= STILL_SPEED) {
            return;   // the top of a vertical throw: for one tick it may not move
        }
        double reach = speed * DT + TOUCH_GAP;
        double clearance = clearance(ball, free);
        String where = String.format(Locale.ROOT, "still at (%s, %s) moving %s L/s, %.3g L from the nearest thing, "
                + "%.3g L from anything that moved", last.x(), last.y(), speed, gap, clearance);
        if (clearance > reach) {
            found.add(new Violation(Violation.Kind.FROZEN, tick, ball.name(), speed, where));
        } else {
            found.add(new Violation(Violation.Kind.HOVERING, tick, ball.name(), gap, where));
        }
    }

    /**
     * How far the ball is from everything it could have met in the tick: walls and still gizmos where they are, the
     * box each flipper swings in, and the path of every other ball from where it was to where it is (taken straight).
     */
    private double clearance(BallView ball, List<BallView> free) {
        double x = ball.position().x();
        double y = ball.position().y();
        double nearest = Math.min(Math.min(x - R, SIZE - R - x), Math.min(y - R, SIZE - R - y));
        for (Body body : still) {
            nearest = Math.min(nearest, body.solid().signedDistance(x, y) - R);
        }
        for (Body box : flipperBoxes) {
            nearest = Math.min(nearest, box.solid().signedDistance(x, y) - R);
        }
        for (Gizmo cell : switching) {
            nearest = Math.min(nearest, Bodies.of(cell).signedDistance(x, y) - R);   // there or not, it was near
        }
        for (Gizmo absorber : fired) {
            // docs/rules.md, "Gizmos": a fired ball leaves the top at 50 L/s; in a tick its centre goes at most that
            // far above it
            double above = Math.max(absorber.y() - R - LAUNCH_SPEED * DT - y, Math.max(0, y - absorber.y() - R));
            double across = Math.max(0, Math.max(absorber.x() - x, x - absorber.x() - absorber.width()));
            nearest = Math.min(nearest, Math.hypot(Math.max(0, above), across) - 2 * R);
        }
        for (BallView other : free) {
            BallAt was = before.get(other.name());
            if (other == ball) {
                continue;
            }
            Point now = new Point(other.position().x(), other.position().y());
            Point from = was == null || was.captured() ? now : new Point(was.x(), was.y());
            nearest = Math.min(nearest, Point.distanceToSegment(x, y, from, now) - 2 * R);
        }
        return nearest;
    }

    private static double kinetic(List<BallView> free) {
        double sum = 0;
        for (BallView ball : free) {
            double vx = ball.velocity().x();
            double vy = ball.velocity().y();
            sum += (vx * vx + vy * vy) / 2;
        }
        return sum;
    }

    private void remember(List<BallView> balls, Map<String, Double> gapOf) {
        before.clear();
        known.clear();
        List<BallView> free = new ArrayList<>();
        for (BallView ball : balls) {
            known.add(ball.name());
            before.put(ball.name(), new BallAt(ball.position().x(), ball.position().y(), ball.velocity().x(),
                    ball.velocity().y(), ball.isCaptured(), gapOf.getOrDefault(ball.name(), Double.NaN)));
            if (!ball.isCaptured()) {
                free.add(ball);
            }
        }
        kineticBefore = kinetic(free);
    }
}
