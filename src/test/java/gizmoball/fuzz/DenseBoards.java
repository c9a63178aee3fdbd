package gizmoball.fuzz;

import gizmoball.model.gizmo.Setting;
import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.model.loop.TriggerSource;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

/**
 * Random dense boards from a seed, as players build them (issue 20, "Your own fuzz"): bumpers of every kind in every
 * rotation (accelerators, sinks, gates, drop targets and portals among them, issue 22, except where energy must be
 * kept; the gates and drop targets switched by keys and hits, most portals paired) packed in blocks, spinners turning
 * either way (added last, keys reverse, start and stop them, bumpers trigger them), corridors one or two cells wide,
 * checkerboards and scattered; flippers in pockets of bumpers, in facing pairs (tongs) and in clumps, some starting
 * part-way through a swing; absorbers along the floor and elsewhere, many firing themselves; 5-40 balls placed free,
 * touching gizmos, flippers (their pivot ends too) and each other, at up to 100 L/s, and on one board in three a walled
 * pocket packed with touching balls; on one board in three with extension gizmos, spawners (issue 39) fed by keys, hits
 * on themselves and on bumpers, and on some by every hit on the outer walls, which fills the board to its 200 balls;
 * keys bound to the flippers and absorbers and a script pressing them. Gravity and
 * friction vary, zero included; about one board in seven has neither, nor flippers nor absorbers, so that its kinetic
 * energy must be kept.
 *
 * <p>Every board is built through {@link Board}'s editing operations, so it is a board a player could build: a
 * placement the board refuses just means another spot is tried. The same seed always gives the same board and
 * script ({@link SplittableRandom}, no other source of chance).
 */
public final class DenseBoards {
    /** Key codes the boards bind: letters, space and the arrows (any code works; these read well in a file). */
    private static final int[] KEY_CODES = {32, 37, 38, 39, 40, 65, 68, 70, 74, 75, 76, 77, 81, 83, 87, 88, 90};
    private static final GizmoKind[] BUMPERS = {GizmoKind.SQUARE, GizmoKind.CIRCLE, GizmoKind.TRIANGLE};
    /**
     * The extension gizmos of a fixed place, drawn among the bumpers of a board whose energy need not be kept; the
     * gates and drop targets among them are wired to switch in play.
     */
    private static final GizmoKind[] EXTENSIONS = {GizmoKind.ACCELERATOR, GizmoKind.SINK, GizmoKind.DROP_TARGET,
            GizmoKind.GATE, GizmoKind.PORTAL};
    private static final int SIZE = Board.SIZE;

    private final SplittableRandom random;
    /**
     * The spinners' own chance: they are drawn last, into what is free, from a stream of their own, so that every
     * board is the one it was before spinners were drawn, with spinners added (issue 22).
     */
    private final SplittableRandom spinnerRandom;
    private static final long SPINNER_STREAM = 0x5b1_22L;
    /**
     * The packed pocket's chance: a stream of its own too, so that a board with a pocket is its old board plus the
     * pocket.
     */
    private final SplittableRandom pocketRandom;
    private static final long POCKET_STREAM = 0x90c_20L;
    /** The spawners' chance: a stream of their own, drawn last, so that a board with spawners is its old board plus them. */
    private final SplittableRandom spawnerRandom;
    private static final long SPAWNER_STREAM = 0x5fa_39L;
    /** The most balls a board has: a packed pocket fills up to it. */
    private static final int MOST_BALLS = 40;
    private final Board board = new Board();
    private final List<String> recipe = new ArrayList<>();
    private final List<String> bumpers = new ArrayList<>();
    private final List<String> flippers = new ArrayList<>();
    private final List<String> absorbers = new ArrayList<>();
    private final List<String> portals = new ArrayList<>();
    /** Gates and drop targets: solid cells that play switches to nothing and back. */
    private final List<String> switchedCells = new ArrayList<>();
    private final List<Integer> keysUsed = new ArrayList<>();
    private int serial;

    private DenseBoards(long seed) {
        random = new SplittableRandom(seed);
        spinnerRandom = new SplittableRandom(seed ^ SPINNER_STREAM);
        pocketRandom = new SplittableRandom(seed ^ POCKET_STREAM);
        spawnerRandom = new SplittableRandom(seed ^ SPAWNER_STREAM);
    }

    /** The board of {@code seed} with a key script for {@code ticks} ticks of play. */
    public static FuzzCase generate(long seed, int ticks) {
        DenseBoards generator = new DenseBoards(seed);
        Board board = generator.build();
        KeyScript keys = KeyScripts.random(generator.random, generator.keysUsed, ticks);
        return new FuzzCase(seed, board, keys, ticks, String.join("; ", generator.recipe));
    }

    /** Whether the extension gizmos are drawn too: not on a board whose kinetic energy must be kept. */
    private boolean extensions;

    private Board build() {
        boolean energyKept = random.nextInt(7) == 0;
        extensions = !energyKept;
        physics(energyKept);
        if (!energyKept) {
            absorbers();
            flippers();
        }
        packBumpers();
        pairPortals();
        if (!energyKept) {
            wire();
        }
        int balls = new BallPlacer(random, board, this::nextName).place(5 + random.nextInt(MOST_BALLS - 4));
        recipe.add(balls + " balls");
        if (!energyKept) {
            spinners();
        }
        if (pocketRandom.nextInt(3) == 0) {
            packedPocket(MOST_BALLS - balls);
        }
        if (extensions) {
            spawners();
        }
        return board;
    }

    private String nextName(String prefix) {
        return prefix + serial++;
    }

    private void physics(boolean energyKept) {
        double gravity;
        double mu;
        double mu2;
        if (energyKept) {
            gravity = 0;
            mu = 0;
            mu2 = 0;
            recipe.add("energy kept");
        } else {
            int g = random.nextInt(20);
            gravity = g < 4 ? 0 : g < 10 ? Board.DEFAULT_GRAVITY : g < 17 ? round(random.nextDouble(1, 80))
                    : g < 18 ? round(random.nextDouble(80, 200)) : -round(random.nextDouble(1, 30));
            int f = random.nextInt(10);
            double most = f == 9 ? 1 : 0.3;
            mu = f < 3 ? 0 : f < 6 ? Board.DEFAULT_MU : round(random.nextDouble(0, most));
            mu2 = f < 3 ? 0 : f < 6 ? Board.DEFAULT_MU2 : round(random.nextDouble(0, most));
        }
        board.setGravity(gravity);
        board.setFriction(mu, mu2);
        recipe.add(String.format(Locale.ROOT, "gravity %s, friction %s %s", gravity, mu, mu2));
    }

    /** Three decimals, as a board author types them. */
    private static double round(double value) {
        return Math.round(value * 1000) / 1000.0;
    }

    // ------------------------------------------------------------------------------------------------ absorbers

    private void absorbers() {
        if (random.nextInt(3) > 0) {
            boolean wall = random.nextInt(4) == 0;
            int x1 = wall ? 0 : random.nextInt(12);
            int x2 = wall ? SIZE : Math.min(SIZE, x1 + 1 + random.nextInt(SIZE - x1));
            int height = random.nextInt(4) == 0 ? 2 : 1;
            absorber(x1, SIZE - height, x2, SIZE, random.nextInt(5) > 0);
        }
        int more = random.nextInt(4);
        for (int i = 0; i < more; i++) {
            int x1 = random.nextInt(SIZE);
            int y1 = random.nextInt(SIZE);
            absorber(x1, y1, Math.min(SIZE, x1 + 1 + random.nextInt(8)), Math.min(SIZE, y1 + 1 + random.nextInt(4)),
                    random.nextBoolean());
        }
        recipe.add(absorbers.size() + " absorbers");
    }

    private void absorber(int x1, int y1, int x2, int y2, boolean firesItself) {
        String name = nextName("A");
        try {
            board.addAbsorber(name, x1, y1, x2, y2);
        } catch (BoardEditException refused) {
            return;
        }
        absorbers.add(name);
        if (firesItself) {
            board.connect(TriggerSource.gizmo(name), name);
        }
    }

    // ------------------------------------------------------------------------------------------------ flippers

    private void flippers() {
        int pockets = random.nextInt(6);
        for (int i = 0; i < pockets; i++) {
            pocket();
        }
        int tongs = random.nextInt(4);
        for (int i = 0; i < tongs; i++) {
            tongs();
        }
        int clumps = random.nextInt(3);
        for (int i = 0; i < clumps; i++) {
            clump();
        }
        for (String flipper : flippers) {
            if (random.nextInt(5) == 0) {
                double degrees = random.nextInt(3) == 0 ? 90 * random.nextInt(2) : random.nextDouble(0, 90);
                board.setFlipperState(flipper, degrees, random.nextBoolean());
            }
        }
        recipe.add(String.format(Locale.ROOT, "%d flippers (%d pockets, %d tongs, %d clumps)", flippers.size(),
                pockets, tongs, clumps));
    }

    private GizmoKind flipperKind() {
        return random.nextBoolean() ? GizmoKind.LEFT_FLIPPER : GizmoKind.RIGHT_FLIPPER;
    }

    /** A flipper with bumpers in the cells around its box. */
    private void pocket() {
        int x = random.nextInt(SIZE - 1);
        int y = random.nextInt(SIZE - 1);
        if (flipper(flipperKind(), x, y, random.nextInt(4)) == null) {
            return;
        }
        double fill = random.nextDouble(0.3, 1);
        for (int cy = y - 1; cy <= y + 2; cy++) {
            for (int cx = x - 1; cx <= x + 2; cx++) {
                boolean ring = cx < x || cx > x + 1 || cy < y || cy > y + 1;
                if (ring && random.nextDouble() < fill) {
                    bumper(randomBumper(), cx, cy, random.nextInt(4));
                }
            }
        }
    }

    /**
     * A left and a right flipper facing each other with a gap of 0-2 cells between their boxes, the pair turned as a
     * whole by 0-3 quarter turns, so that their tips meet when both are up.
     */
    private void tongs() {
        int gap = random.nextInt(3);
        int turns = random.nextInt(4);
        int long_ = 4 + gap;
        boolean across = turns % 2 == 0;
        int x = random.nextInt(SIZE - (across ? long_ : 2) + 1);
        int y = random.nextInt(SIZE - (across ? 2 : long_) + 1);
        // Before turning: left box at 0, right box at 2 + gap; a quarter turn clockwise sends left to top, and so on.
        int far = 2 + gap;
        int[][] offsets = {{0, 0, far, 0}, {0, 0, 0, far}, {far, 0, 0, 0}, {0, far, 0, 0}};
        int[] o = offsets[turns];
        flipper(GizmoKind.LEFT_FLIPPER, x + o[0], y + o[1], turns);
        flipper(GizmoKind.RIGHT_FLIPPER, x + o[2], y + o[3], turns);
    }

    /** Two to four flippers of any kind and rotation side by side in a small region. */
    private void clump() {
        int x = random.nextInt(SIZE - 3);
        int y = random.nextInt(SIZE - 3);
        int count = 2 + random.nextInt(3);
        for (int i = 0; i < count; i++) {
            flipper(flipperKind(), x + 2 * random.nextInt(2), y + 2 * random.nextInt(2), random.nextInt(4));
        }
    }

    private String flipper(GizmoKind kind, int x, int y, int turns) {
        String name = gizmo(kind, kind == GizmoKind.LEFT_FLIPPER ? "LF" : "RF", x, y, turns);
        if (name != null) {
            flippers.add(name);
        }
        return name;
    }

    // ------------------------------------------------------------------------------------------------ spinners

    /**
     * Up to three spinners (issue 22) where there is room once the rest is built (among the bumpers, on balls that
     * its bar will bat), at speeds from a quarter turn to three turns a second either way, some starting at an
     * angle of their own; the keys already bound also reverse, start or stop them, and the bumpers trigger them.
     */
    private void spinners() {
        SplittableRandom r = spinnerRandom;
        int count = r.nextInt(4);
        List<String> spinners = new ArrayList<>();
        for (int i = 0; i < count * 20 && spinners.size() < count; i++) {
            String name = nextName("SN");
            try {
                board.addGizmo(GizmoKind.SPINNER, name, r.nextInt(SIZE - 1), r.nextInt(SIZE - 1));
            } catch (BoardEditException refused) {
                continue;   // taken, or on a ball: another spot
            }
            spinners.add(name);
            double turns = r.nextInt(3) == 0 ? 1 : round(r.nextDouble(0.25, 3));
            board.set(name, new Setting.Speed(r.nextBoolean() ? turns : -turns));
            if (r.nextInt(3) == 0) {
                try {
                    board.setSpinnerState(name, r.nextDouble(0, 2 * Math.PI), r.nextInt(4) > 0);
                } catch (BoardEditException onABall) {
                    // the bar there would lie on a ball: it starts lying flat
                }
            }
            Action[] actions = {Action.REVERSE, Action.START, Action.STOP};
            for (int k = 0; k < 2 && !keysUsed.isEmpty(); k++) {
                try {
                    board.bindKey(keysUsed.get(r.nextInt(keysUsed.size())), KeyEdge.DOWN, name,
                            Order.of(actions[r.nextInt(actions.length)]));
                } catch (BoardEditException duplicate) {
                    // the same key drawn again for the spinner: one binding fewer
                }
            }
            if (!bumpers.isEmpty() && r.nextBoolean()) {
                board.connect(TriggerSource.gizmo(bumpers.get(r.nextInt(bumpers.size()))), name);
            }
        }
        recipe.add(spinners.size() + " spinners");
    }

    // ------------------------------------------------------------------------------------------------ spawners

    /**
     * On one board in three, one to three spawners (issue 39) in free cells, facing any way, each launching its balls
     * at rest or at up to 60 L/s in any direction; each spawns at a key already bound (never a new one: the script
     * stays the board's old one), at a hit on itself or on a bumper; on one such board in two a spawner also spawns at
     * every hit on the outer walls, a flood that fills the board to its 200 balls (the slowest boards of issue 39).
     */
    private void spawners() {
        SplittableRandom r = spawnerRandom;
        if (r.nextInt(3) > 0) {
            return;
        }
        int count = 1 + r.nextInt(3);
        boolean flood = r.nextBoolean();
        List<String> spawners = new ArrayList<>();
        for (int i = 0; i < count * 20 && spawners.size() < count; i++) {
            String name = gizmo(GizmoKind.SPAWNER, "SP", r.nextInt(SIZE), r.nextInt(SIZE), r.nextInt(4));
            if (name == null) {
                continue;
            }
            spawners.add(name);
            double speed = r.nextInt(4) == 0 ? 0 : round(r.nextDouble(1, 60));
            double angle = r.nextDouble(0, 2 * Math.PI);
            board.set(name, new Setting.Launch(round(speed * StrictMath.cos(angle)), round(speed * StrictMath.sin(angle))));
            if (!keysUsed.isEmpty() && r.nextBoolean()) {
                try {
                    board.bindKey(keysUsed.get(r.nextInt(keysUsed.size())), r.nextBoolean() ? KeyEdge.DOWN
                            : KeyEdge.CHANGE, name);
                } catch (BoardEditException duplicate) {
                    // the key already spawns here: one binding fewer
                }
            }
            if (r.nextBoolean()) {
                board.connect(TriggerSource.gizmo(name), name);
            }
            if (!bumpers.isEmpty() && r.nextBoolean()) {
                board.connect(TriggerSource.gizmo(bumpers.get(r.nextInt(bumpers.size()))), name);
            }
        }
        if (flood && !spawners.isEmpty()) {
            board.connect(TriggerSource.OUTER_WALLS, spawners.get(0));
        }
        recipe.add(spawners.size() + " spawners" + (flood && !spawners.isEmpty() ? ", one fed by the walls" : ""));
    }

    /**
     * A pocket packed with touching balls (issue 20's clusters of touching balls): a rectangle of 2 to 6 by 2 to 6 free
     * cells, walled with bumpers where its border is free, its balls on a square or a hexagonal lattice of touching
     * balls (2R apart; the hexagonal rows touch only to rounding) filling 60 to 100 % of its places, as many as keep
     * the board to {@link #MOST_BALLS}, each at rest, slow or fast as the other balls are.
     */
    private void packedPocket(int room) {
        SplittableRandom r = pocketRandom;
        boolean[][] taken = takenCells();
        for (int attempt = 0; attempt < 400 && room > 0; attempt++) {
            int w = 2 + r.nextInt(5);
            int h = 2 + r.nextInt(5);
            int x = r.nextInt(SIZE - w + 1);
            int y = r.nextInt(SIZE - h + 1);
            if (!free(taken, x, y, w, h)) {
                continue;
            }
            for (int cx = x - 1; cx <= x + w; cx++) {
                for (int cy = y - 1; cy <= y + h; cy++) {
                    boolean border = cx < x || cx >= x + w || cy < y || cy >= y + h;
                    if (border && cx >= 0 && cy >= 0 && cx < SIZE && cy < SIZE && !taken[cx][cy]) {
                        bumper(r.nextInt(4) == 0 ? BUMPERS[r.nextInt(BUMPERS.length)] : GizmoKind.SQUARE, cx, cy,
                                r.nextInt(4));
                    }
                }
            }
            boolean hexagonal = r.nextBoolean();
            List<Point> places = lattice(x, y, w, h, hexagonal);
            int wanted = Math.min(room, (int) Math.ceil(r.nextDouble(0.6, 1) * places.size()));
            BallPlacer placer = new BallPlacer(r, board, this::nextName);
            int placed = 0;
            for (int i = 0; i < places.size() && placed < wanted; i++) {
                int j = i + r.nextInt(places.size() - i);
                Point place = places.set(j, places.get(i));
                places.set(i, place);
                placed += placer.placeAt(place) ? 1 : 0;
            }
            recipe.add(String.format(Locale.ROOT, "a pocket of %dx%d cells packed with %d balls (%s)", w, h, placed,
                    hexagonal ? "hexagonal" : "square"));
            return;
        }
    }

    /** The cells some gizmo covers. */
    private boolean[][] takenCells() {
        boolean[][] taken = new boolean[SIZE][SIZE];
        for (Gizmo g : board.gizmos()) {
            for (int cx = g.x(); cx < g.x() + g.width(); cx++) {
                for (int cy = g.y(); cy < g.y() + g.height(); cy++) {
                    taken[cx][cy] = true;
                }
            }
        }
        return taken;
    }

    private static boolean free(boolean[][] taken, int x, int y, int w, int h) {
        for (int cx = x; cx < x + w; cx++) {
            for (int cy = y; cy < y + h; cy++) {
                if (taken[cx][cy]) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * The centres of touching balls filling the rectangle of cells: a square lattice 2R apart, or hexagonal rows
     * sqrt(3) R apart, every other one shifted by R.
     */
    private static List<Point> lattice(int x, int y, int w, int h, boolean hexagonal) {
        double r = Board.BALL_RADIUS;
        double rowStep = hexagonal ? Math.sqrt(3) * r : 2 * r;
        List<Point> places = new ArrayList<>();
        for (int row = 0; y + r + row * rowStep <= y + h - r; row++) {
            double shift = hexagonal && row % 2 == 1 ? r : 0;
            for (int col = 0; x + r + shift + col * 2 * r <= x + w - r; col++) {
                places.add(new Point(x + r + shift + col * 2 * r, y + r + row * rowStep));
            }
        }
        return places;
    }

    // ------------------------------------------------------------------------------------------------ bumpers

    private GizmoKind randomBumper() {
        if (extensions && random.nextInt(6) == 0) {
            return EXTENSIONS[random.nextInt(EXTENSIONS.length)];
        }
        return BUMPERS[random.nextInt(BUMPERS.length)];
    }

    private void packBumpers() {
        int blocks = random.nextInt(4);
        for (int i = 0; i < blocks; i++) {
            block();
        }
        int corridors = random.nextInt(3);
        for (int i = 0; i < corridors; i++) {
            corridor();
        }
        if (random.nextInt(4) == 0) {
            checkerboard();
        }
        double density = random.nextInt(8) == 0 ? random.nextDouble(0.6, 0.9) : random.nextDouble(0.05, 0.6);
        int scattered = (int) (density * SIZE * SIZE);
        for (int i = 0; i < scattered; i++) {
            bumper(randomBumper(), random.nextInt(SIZE), random.nextInt(SIZE), random.nextInt(4));
        }
        recipe.add(String.format(Locale.ROOT, "%d bumpers (%d blocks, %d corridors, scatter %.2f)", bumpers.size(),
                blocks, corridors, density));
    }

    /** Portals in pairs as they were placed (one in five left alone: a wall), often facing walls and bumpers. */
    private void pairPortals() {
        for (int i = 0; i + 1 < portals.size(); i += 2) {
            if (random.nextInt(5) > 0) {
                board.set(portals.get(i), Setting.Pair.with(portals.get(i + 1)));
            }
        }
        if (!portals.isEmpty()) {
            recipe.add(portals.size() + " portals");
        }
    }

    /** A rectangle of cells nearly all filled with bumpers. */
    private void block() {
        int x = random.nextInt(SIZE);
        int y = random.nextInt(SIZE);
        int width = 2 + random.nextInt(5);
        int height = 1 + random.nextInt(4);
        double fill = random.nextDouble(0.7, 1);
        for (int cy = y; cy < y + height; cy++) {
            for (int cx = x; cx < x + width; cx++) {
                if (random.nextDouble() < fill) {
                    bumper(randomBumper(), cx, cy, random.nextInt(4));
                }
            }
        }
    }

    /** Two walls of squares with a channel of 1 or 2 cells between them, a bumper of any kind closing one end. */
    private void corridor() {
        int width = 1 + random.nextInt(2);
        int length = 2 + random.nextInt(6);
        boolean upright = random.nextBoolean();
        int x = random.nextInt(SIZE);
        int y = random.nextInt(SIZE);
        for (int i = 0; i < length; i++) {
            for (int side : new int[] {0, width + 1}) {
                int cx = upright ? x + side : x + i;
                int cy = upright ? y + i : y + side;
                bumper(GizmoKind.SQUARE, cx, cy, 0);
            }
        }
        for (int j = 1; j <= width; j++) {
            bumper(randomBumper(), upright ? x + j : x + length, upright ? y + length : y + j, random.nextInt(4));
        }
    }

    /** Squares on alternate cells of a region: corners meeting corners. */
    private void checkerboard() {
        int x = random.nextInt(SIZE - 2);
        int y = random.nextInt(SIZE - 2);
        int side = 3 + random.nextInt(5);
        for (int cy = y; cy < y + side; cy++) {
            for (int cx = x; cx < x + side; cx++) {
                if ((cx + cy) % 2 == 0) {
                    bumper(random.nextInt(4) == 0 ? GizmoKind.TRIANGLE : GizmoKind.SQUARE, cx, cy, random.nextInt(4));
                }
            }
        }
    }

    private void bumper(GizmoKind kind, int x, int y, int turns) {
        String name = gizmo(kind, kind.name().substring(0, 1), x, y, turns);
        if (name != null) {
            (kind == GizmoKind.GATE || kind == GizmoKind.DROP_TARGET ? switchedCells
                    : kind == GizmoKind.PORTAL ? portals : bumpers).add(name);
        }
    }

    /**
     * Adds the gizmo and turns it as far as the balls let it, or returns null where the board refuses it (off the
     * board, or taken).
     */
    private String gizmo(GizmoKind kind, String prefix, int x, int y, int turns) {
        if (x < 0 || y < 0 || x + kind.width() > SIZE || y + kind.height() > SIZE) {
            return null;
        }
        String name = nextName(prefix);
        try {
            board.addGizmo(kind, name, x, y);
        } catch (BoardEditException refused) {
            return null;
        }
        try {
            for (int t = 0; t < turns; t++) {
                board.rotate(name);
            }
        } catch (BoardEditException onABall) {
            // turned, it would lie on a ball (a packed pocket's wall): it stays as it has turned so far
        }
        return name;
    }

    // ------------------------------------------------------------------------------------------------ wiring

    /** Keys for flippers and absorbers, and connections from bumpers, the walls and flippers to them. */
    private void wire() {
        for (String flipper : flippers) {
            if (random.nextInt(7) == 0) {
                continue;
            }
            int key = key();
            int how = random.nextInt(12);
            if (how < 8) {
                board.bindKey(key, KeyEdge.DOWN, flipper);
                board.bindKey(key, KeyEdge.UP, flipper);
            } else if (how == 8) {
                // Up with one key, down with another (or the same one, drawn again).
                board.bindKey(key, KeyEdge.DOWN, flipper);
                board.bindKey(key(), KeyEdge.UP, flipper);
            } else {
                KeyEdge[] edges = {KeyEdge.DOWN, KeyEdge.UP, KeyEdge.CHANGE};
                board.bindKey(key, edges[how - 9], flipper);
            }
        }
        for (String absorber : absorbers) {
            if (random.nextBoolean()) {
                board.bindKey(key(), random.nextBoolean() ? KeyEdge.DOWN : KeyEdge.CHANGE, absorber);
            }
        }
        List<String> targets = new ArrayList<>(flippers);
        targets.addAll(absorbers);
        for (String cell : switchedCells) {
            // A gate toggles, a drop target rises, at a hit on a bumper or a wall, or while a key says: over balls too.
            if (random.nextBoolean() || bumpers.isEmpty()) {
                board.bindKey(key(), random.nextBoolean() ? KeyEdge.DOWN : KeyEdge.CHANGE, cell);
            } else {
                board.connect(TriggerSource.gizmo(bumpers.get(random.nextInt(bumpers.size()))), cell);
            }
        }
        int connections = targets.isEmpty() ? 0 : random.nextInt(6);
        for (int i = 0; i < connections; i++) {
            String target = targets.get(random.nextInt(targets.size()));
            int from = random.nextInt(4);
            TriggerSource source = from == 0 || bumpers.isEmpty() ? TriggerSource.OUTER_WALLS
                    : from == 1 ? TriggerSource.gizmo(targets.get(random.nextInt(targets.size())))
                    : TriggerSource.gizmo(bumpers.get(random.nextInt(bumpers.size())));
            try {
                board.connect(source, target);
            } catch (BoardEditException duplicate) {
                // already connected: one connection fewer
            }
        }
        recipe.add(keysUsed.size() + " keys, " + board.connections().size() + " connections");
    }

    /** A key already used on the board (often: flippers share keys) or a new one. */
    private int key() {
        if (!keysUsed.isEmpty() && random.nextBoolean()) {
            return keysUsed.get(random.nextInt(keysUsed.size()));
        }
        int key = KEY_CODES[random.nextInt(KEY_CODES.length)];
        if (!keysUsed.contains(key)) {
            keysUsed.add(key);
        }
        return key;
    }
}
