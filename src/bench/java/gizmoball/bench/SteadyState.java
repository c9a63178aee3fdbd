package gizmoball.bench;

import gizmoball.boardfile.BoardFileException;
import gizmoball.boardfile.BoardFiles;
import gizmoball.boardfile.LoadResult;
import gizmoball.model.Board;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.loop.TriggerSource;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.GuardCounts;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.Stage;
import gizmoball.model.loop.TickReport;
import physics.Vect;

import java.io.IOException;
import java.io.PrintStream;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * What a tick costs once play has settled (issue 10): most of a real game is balls lying in V's, on bumpers and in
 * piles, not the first second of flight.
 * <ul>
 *     <li>Steady state: each shipped board and the 100-ball peer board, ticked at 1/60 s through a warm-up, then
 *     every tick of the window timed alone: mean, p99 and max, collisions and zero-time collisions per tick, the
 *     balls asleep and awake at the end, and the guards that fired in the window.</li>
 *     <li>A sleeping pile against the same board without balls: the cost of balls that do nothing.</li>
 *     <li>A guard survey: every shipped and every loadable peer board for a fixed number of ticks.</li>
 * </ul>
 * Each tick is timed by wall time ({@code System.nanoTime}, tens of nanoseconds to read): a frame is late by wall
 * time, garbage collection and the machine's other work included. On a shared machine that work can make a fast
 * model look slow, so a second run of the same board times each tick by the thread's CPU clock, which costs about
 * 2 us a read on these machines (as much as a small board's tick): that run's reads are kept out of the first.
 */
final class SteadyState {

    static final double DT = Board.DEFAULT_TICK;
    /** The peer board with 100 balls (MIT 6.170 staff test), measured beside the shipped boards. */
    static final String MANY_BALLS = "dwctsai__mit-6.170-gizmoball-3d__src__stafftests__many-balls.gb";
    /** The board whose every tick is charted (and the one {@link Targets} sets the most for). */
    static final String CHARTED = "stress.txt";
    /** Ticks per point of the chart. */
    static final int BIN = 100;

    /**
     * Tick numbers of each part. Steady state: warm-up ticks [0, from), measured [from, to). Pile: ticks to settle,
     * then ticks timed of each board. Survey: ticks per board.
     */
    record Windows(int from, int to, int pileSettle, int pileTicks, int surveyTicks) {
        static final Windows FULL = new Windows(3_000, 15_000, 300, 60_000, 5_000);
        static final Windows QUICK = new Windows(600, 1_800, 300, 6_000, 1_000);
    }

    /**
     * One board's window, after {@code warmPlays} throw-away plays of a copy ({@link CompilerWarmUp}). Times in
     * microseconds, by wall clock and by the thread's CPU clock (a second run of the same board; play is
     * deterministic, so it is the same ticks); bytes the ticking thread allocated per tick over
     * the window, in that second run; guards are those fired within the window; the slowest tick is the slowest by CPU
     * time.
     */
    record Row(String board, int gizmos, int balls, int from, int to, int warmPlays, double meanUs, double p99Us,
               double maxUs, double cpuMeanUs, double cpuP99Us, double cpuMaxUs, double bytesPerTick,
               double meanCollisions, int maxCollisions, double meanZeroTime, int maxZeroTime, int awake, int asleep,
               GuardCounts guards, long gcPauses, long gcMillis, int slowestTick, int slowestCollisions,
               Map<Stage, Long> stageNanos) {
    }

    /** A row and the time of every tick from 0 (for the chart). */
    record Run(Row row, long[] tickNanos) {
    }

    /**
     * The sleeping pile and the same board without balls, each {@code ticks} ticks after settling, timed in
     * alternating blocks. {@code moved}: the farthest any ball of the pile went while it was timed.
     */
    record Pile(int balls, int asleepAfterSettle, int asleepAtEnd, double pileUs, double emptyUs, double moved) {
        double ratio() {
            return pileUs / emptyUs;
        }

        boolean allAsleep() {
            return asleepAfterSettle == balls && asleepAtEnd == balls;
        }
    }

    /**
     * A board of the survey with the guards it fired and its jams (a flipper stalled by a ball it cannot squeeze out:
     * physics, reported beside the guards, not among them); {@code failure} when a tick threw.
     */
    record Surveyed(String board, int balls, GuardCounts guards, long jams, Optional<String> failure) {
    }

    /** The part's findings, for {@link Targets}. */
    record Result(List<Row> rows, Pile pile, Survey survey) {
        Optional<Row> row(String board) {
            return rows.stream().filter(r -> r.board().equals(board)).findFirst();
        }
    }

    record Survey(int ticks, int filesSeen, List<Surveyed> boards) {
        List<Surveyed> firing() {
            return boards.stream().filter(b -> b.guards().total() > 0)
                    .sorted(Comparator.comparingLong((Surveyed b) -> b.guards().total()).reversed()).toList();
        }

        GuardCounts totals() {
            return boards.stream().map(Surveyed::guards).reduce(GuardCounts.NONE, GuardCounts::plus);
        }

        long jams() {
            return boards.stream().mapToLong(Surveyed::jams).sum();
        }

        long jamming() {
            return boards.stream().filter(b -> b.jams() > 0).count();
        }
    }

    /** The JDK's own ThreadMXBean, which also counts the bytes a thread allocates. */
    private static final com.sun.management.ThreadMXBean THREADS =
            (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();

    private SteadyState() {
    }

    /**
     * The whole part: the steady-state table (and the chart of {@link #CHARTED}), the pile and the survey, printed,
     * with CSV files and the chart in {@code dir}. Without a peer folder the 100-ball board and the peer boards of
     * the survey are left out, with a note. The tables go on {@code page} too; the findings are returned for the
     * targets.
     */
    static Result run(PrintStream out, Path shipped, Optional<Path> peers, Windows w, Path dir, ResultsPage page)
            throws IOException {
        if (peers.isEmpty()) {
            out.println("note: no peer-board folder (--peers DIR; gradle passes ../shared/peer-boards when it exists): "
                    + "the 100-ball peer board and the peer boards of the guard survey are left out");
        }
        // Wall times on a shared machine mean little without its load: said at both ends of the part.
        printLoad(out, "start");
        List<NamedBoard> boards = new ArrayList<>(boards(shipped, peers));
        boards.addAll(builtBoards(w));
        List<Row> rows = new ArrayList<>();
        for (NamedBoard board : boards) {
            Run run = (Run) Isolated.call(SteadyState.class, "measureNamed", shipped, peers, w, board.name());
            rows.add(run.row());
            if (board.name().equals(CHARTED)) {
                writeBins(dir.resolve("steady-state-ticks.csv"), run.tickNanos());
                Charts.tickCost(dir, CHARTED, bins(run.tickNanos()), BIN, w.from());
            }
        }
        printRows(out, rows, w);
        writeRows(dir.resolve("steady-state.csv"), rows);
        page.steadyState(rows, w);

        Pile pile = comparePile(w);
        printPile(out, pile, w);
        writePile(dir.resolve("sleeping-pile.csv"), pile);
        page.pile(pile);

        Survey survey = survey(shipped, peers, w.surveyTicks());
        printSurvey(out, survey, w, 8);
        writeSurvey(dir.resolve("guard-survey.csv"), survey);
        page.survey(survey);

        printLoad(out, "end");
        return new Result(rows, pile, survey);
    }

    private static void printLoad(PrintStream out, String when) {
        out.printf(Locale.ROOT, "machine at the %s of the steady-state part: load average %.2f over the last minute, "
                        + "%d processors%n", when, ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(),
                Runtime.getRuntime().availableProcessors());
    }

    /** The boards of the steady-state table: the shipped ones, then the 100-ball peer board when peers is given. */
    static List<NamedBoard> boards(Path shipped, Optional<Path> peers) throws IOException {
        List<NamedBoard> boards = new ArrayList<>();
        for (Path file : files(shipped, ".txt")) {
            try {
                boards.add(new NamedBoard(String.valueOf(file.getFileName()), BoardFiles.load(file)));
            } catch (BoardFileException e) {
                throw new IOException("cannot load " + file + ": " + e.getMessage(), e);
            }
        }
        if (peers.isPresent()) {
            Path file = peers.get().resolve(MANY_BALLS);
            LoadResult loaded = BoardFiles.loadSkippingBadLines(file);
            if (!loaded.skippedLines().isEmpty()) {
                throw new IOException(file + " lost lines on loading: " + loaded.skippedLines());
            }
            boards.add(new NamedBoard(MANY_BALLS, loaded.board()));
        }
        return boards;
    }

    /**
     * The boards the benchmark builds: {@link #ONE_BALL}, {@link #MANY_IN_PLAY} and {@link #SPAWNED} (these two in
     * their own, earlier windows).
     */
    static List<NamedBoard> builtBoards(Windows w) {
        boolean full = w.equals(Windows.FULL);
        return List.of(new NamedBoard(ONE_BALL, oneBallAmongFiveBumpers()),
                new NamedBoard(MANY_IN_PLAY, RandomBoards.generate(Scaling.SEED, Scaling.GIZMOS_WHILE_BALLS_GROW, 200),
                        Optional.of(full ? IN_PLAY : IN_PLAY_QUICK)),
                new NamedBoard(SPAWNED, spawnerBoard(), Optional.of(full ? SPAWNING : SPAWNING_QUICK)));
    }

    /**
     * A board of the table and the ticks it is measured over: the table's windows, or its own where what it shows
     * is not the settled state ({@link #IN_PLAY}).
     */
    record NamedBoard(String name, Board board, Optional<Windows> windows) {
        NamedBoard(String name, Board board) {
            this(name, board, Optional.empty());
        }

        Windows windowsOr(Windows standard) {
            return windows.orElse(standard);
        }
    }

    /** The board of one ball in flight among five bumpers, no gravity or friction: what a tick costs at least. */
    static final String ONE_BALL = "one ball among five bumpers";
    /** The board of 200 balls among 100 bumpers under gravity, timed while they fall, bounce and pile. */
    static final String MANY_IN_PLAY = "200 balls in play";
    /**
     * Ticks of {@link #MANY_IN_PLAY}: from 1 s after load, while most of its balls are still in flight and meeting
     * each other, for 20 s; from 50 s on (the table's window) nearly all of them sleep in piles.
     */
    static final Windows IN_PLAY = new Windows(60, 1_260, 0, 0, 0);
    static final Windows IN_PLAY_QUICK = new Windows(60, 660, 0, 0, 0);

    /** The board of 200 balls that spawners keep filling while sinks take them (issue 39). */
    static final String SPAWNED = "200 balls from spawners";
    /** Ticks of {@link #SPAWNED}: from when it holds 200 balls (by tick 600), for 20 s. */
    static final Windows SPAWNING = new Windows(600, 1_800, 0, 0, 0);
    static final Windows SPAWNING_QUICK = new Windows(600, 1_200, 0, 0, 0);

    /**
     * {@link #MANY_IN_PLAY}'s 100 bumpers under gravity with 10 balls, four spawners along the free top row launching
     * balls sideways at 10 L/s, each spawning at every hit on the outer walls and on itself, and two sinks in the
     * bottom row: it fills to the 200 balls a spawner stops at, and the sinks take balls that the spawners put back,
     * so balls come and go in every second of it.
     */
    static Board spawnerBoard() {
        Board board = RandomBoards.generate(Scaling.SEED, Scaling.GIZMOS_WHILE_BALLS_GROW, 0);
        for (int x : new int[] {3, 4, 5, 8, 9, 10, 13, 14, 15, 19}) {
            board.addBall("B" + x, x + 0.5, 0.5, x % 2 == 0 ? 5 : -5, 3);
        }
        for (int i = 0; i < 4; i++) {
            String name = "SP" + i;
            board.addGizmo(GizmoKind.SPAWNER, name, 1 + 5 * i, 0);
            board.rotate(name);   // its mouth faces right, along the free top row
            board.set(name, new Setting.Launch(10, 2));
            board.connect(TriggerSource.OUTER_WALLS, name);
            board.connect(TriggerSource.gizmo(name), name);
        }
        // The first free cells of the bottom row from x = 4 and from x = 14 (the balls start in the top row).
        for (int x : new int[] {4, 14}) {
            int cell = x;
            while (board.gizmoAt(cell, Board.SIZE - 1).isPresent()) {
                cell++;
            }
            board.addGizmo(GizmoKind.SINK, "SK" + x, cell, Board.SIZE - 1);
        }
        return board;
    }

    /**
     * One ball at 15.8 L/s (13, -9) among two circles, two squares and a triangle, with no gravity or friction: it
     * flies and bounces for ever, so every tick is the loop's fixed cost and one ball's detection.
     */
    static Board oneBallAmongFiveBumpers() {
        Board board = new Board();
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addGizmo(GizmoKind.CIRCLE, "C0", 4, 4);
        board.addGizmo(GizmoKind.SQUARE, "S0", 14, 5);
        board.addGizmo(GizmoKind.TRIANGLE, "T0", 6, 14);
        board.addGizmo(GizmoKind.CIRCLE, "C1", 15, 15);
        board.addGizmo(GizmoKind.SQUARE, "S1", 10, 10);
        board.addBall("B", 2.5, 17.5, 13, -9);
        return board;
    }

    /**
     * Throw-away plays of copies, so that a board does not pay for compiling the loop for what it asks of it
     * ({@link CompilerWarmUp}): the 100-ball board measured in a fresh JVM cost 285 us a tick over ticks 3,000-15,000,
     * then 140 and 113 in the next two runs of the same ticks, as the compiler caught up with its many-ball paths.
     * Returns how many plays it took.
     */
    static int warmUp(Board board, int ticks) {
        return CompilerWarmUp.play(() -> {
            Board copy = board.copy();
            for (int i = 0; i < ticks; i++) {
                copy.tick(DT);
            }
        });
    }

    /**
     * {@link #measure} of the board of the table named {@code name}, made afresh: what {@link #run} asks of each board
     * with a copy of the game's classes of its own ({@link Isolated}), as a JVM that plays only that board.
     */
    static Run measureNamed(Path shipped, Optional<Path> peers, Windows w, String name) throws IOException {
        List<NamedBoard> boards = new ArrayList<>(boards(shipped, peers));
        boards.addAll(builtBoards(w));
        NamedBoard named = boards.stream().filter(b -> b.name().equals(name)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("no board " + name + " in the steady-state table"));
        return measure(named, named.windowsOr(w));
    }

    /** Ticks the board from 0 to the window's end, timing every tick; statistics over the window only. */
    static Run measure(NamedBoard named, Windows w) {
        Board board = named.board();
        int warmPlays = warmUp(board, w.to());
        CpuWindow cpuRun = cpuPerTick(board.copy(), w);
        long[] cpuWindow = cpuRun.nanos();
        board.setStageTiming(true);   // the wall run gives the stages' split; the CPU run reads no stage clock, as play
        long[] nanos = new long[w.to()];
        int[] collisions = new int[w.to()];
        int[] zeroTime = new int[w.to()];
        GuardCounts guards = GuardCounts.NONE;
        long[] gcAtStart = new long[2];
        Map<Stage, Long> stages = new EnumMap<>(Stage.class);
        for (int t = 0; t < w.to(); t++) {
            if (t == w.from()) {
                gcAtStart = garbageCollections();
            }
            long start = System.nanoTime();
            board.tick(DT);
            nanos[t] = System.nanoTime() - start;
            TickReport report = board.lastTick();
            collisions[t] = report.collisions();
            zeroTime[t] = report.zeroTimeCollisions();
            if (t >= w.from()) {
                guards = guards.plus(report.guards());
                report.stageNanos().forEach((stage, n) -> stages.merge(stage, n, Long::sum));
            }
        }
        long[] gcAtEnd = garbageCollections();
        int slowest = 0;
        for (int i = 0; i < cpuWindow.length; i++) {
            slowest = cpuWindow[i] > cpuWindow[slowest] ? i : slowest;
        }
        int slowestTick = w.from() + slowest;
        Arrays.sort(cpuWindow);
        long[] window = Arrays.copyOfRange(nanos, w.from(), w.to());
        Arrays.sort(window);
        int n = window.length;
        TickReport last = board.lastTick();
        Row row = new Row(named.name(), board.gizmos().size(), board.balls().size(), w.from(), w.to(), warmPlays,
                Arrays.stream(window).average().orElse(0) / 1e3, window[p99(n)] / 1e3, window[n - 1] / 1e3, Arrays.stream(cpuWindow).average().orElse(0) / 1e3,
                cpuWindow[p99(n)] / 1e3, cpuWindow[n - 1] / 1e3, cpuRun.bytesPerTick(), mean(collisions, w.from()), max(collisions, w.from()), mean(zeroTime, w.from()),
                max(zeroTime, w.from()), last.ballsAwake(), last.ballsAsleep(), guards, gcAtEnd[0] - gcAtStart[0],
                gcAtEnd[1] - gcAtStart[1], slowestTick, collisions[slowestTick], stages);
        return new Run(row, nanos);
    }

    private static int p99(int n) {
        return (int) Math.ceil(0.99 * n) - 1;
    }

    /** The CPU time of each tick of a window (unsorted), and the bytes the ticking thread allocated per tick in it. */
    record CpuWindow(long[] nanos, double bytesPerTick) {
    }

    /**
     * The thread CPU time of each tick of the window (unsorted), the clock read once between ticks. A read costs
     * about 2 us, which lands in the interval it ends; that cost, the median interval with no tick in it, is
     * taken off every tick. The bytes allocated are read at the window's ends
     * ({@code com.sun.management.ThreadMXBean.getCurrentThreadAllocatedBytes}): the clock's reads allocate nothing.
     */
    private static CpuWindow cpuPerTick(Board board, Windows w) {
        for (int t = 0; t < w.from(); t++) {
            board.tick(DT);
        }
        long[] empty = new long[1_001];
        for (int i = 0; i < empty.length; i++) {
            empty[i] = THREADS.getCurrentThreadCpuTime();
        }
        long[] reads = new long[empty.length - 1];
        for (int i = 0; i < reads.length; i++) {
            reads[i] = empty[i + 1] - empty[i];
        }
        Arrays.sort(reads);
        long readCost = reads[reads.length / 2];
        long[] cpu = new long[w.to() - w.from()];
        long allocatedBefore = THREADS.getCurrentThreadAllocatedBytes();
        long before = THREADS.getCurrentThreadCpuTime();
        for (int i = 0; i < cpu.length; i++) {
            board.tick(DT);
            long after = THREADS.getCurrentThreadCpuTime();
            cpu[i] = Math.max(0, after - before - readCost);
            before = after;
        }
        long allocated = THREADS.getCurrentThreadAllocatedBytes() - allocatedBefore;
        return new CpuWindow(cpu, allocated / (double) cpu.length);
    }

    /**
     * Collections so far and their total milliseconds, over every collector: a tick that a collection interrupts
     * lasts as long as the pause, which is what the max of a small board mostly is.
     */
    private static long[] garbageCollections() {
        long count = 0;
        long millis = 0;
        for (GarbageCollectorMXBean gc : ManagementFactory.getGarbageCollectorMXBeans()) {
            count += Math.max(0, gc.getCollectionCount());
            millis += Math.max(0, gc.getCollectionTime());
        }
        return new long[] {count, millis};
    }

    private static double mean(int[] values, int from) {
        return Arrays.stream(values, from, values.length).average().orElse(0);
    }

    private static int max(int[] values, int from) {
        return Arrays.stream(values, from, values.length).max().orElse(0);
    }

    /**
     * Two squares on the floor, cells (4,19) and (9,19), with the four cells between them filled by three rows of
     * touching balls: 8 on the floor, 7 in their grooves, 6 in those. Each row lies 2r sin 60 deg above the one
     * below, where a ball touches both balls under it.
     */
    static Board pile(boolean withBalls) {
        Board board = new Board();
        board.addGizmo(GizmoKind.SQUARE, "left", 4, 19);
        board.addGizmo(GizmoKind.SQUARE, "right", 9, 19);
        if (withBalls) {
            double r = Board.BALL_RADIUS;
            double rise = 2 * r * Math.sin(Math.toRadians(60));
            int[] rowSizes = {8, 7, 6};
            for (int row = 0; row < rowSizes.length; row++) {
                double y = Board.SIZE - r - row * rise;
                for (int i = 0; i < rowSizes[row]; i++) {
                    board.addBall("p" + row + "_" + i, 5 + r + row * r + i * 2 * r, y, 0, 0);
                }
            }
        }
        return board;
    }

    /**
     * Settles both boards, then times them in alternating blocks of ticks (so that both see the same machine load)
     * until each has run {@code ticks}. A tick of a board that does nothing lasts a few microseconds, so the clock
     * is read once per block, not per tick; and it is the thread's CPU clock: on a busy machine a block's wall time
     * is mostly other processes' turns, which would make the ratio a measure of the load.
     */
    static Pile comparePile(Windows w) {
        Board pile = pile(true);
        Board empty = pile(false);
        for (int t = 0; t < w.pileSettle(); t++) {
            pile.tick(DT);
            empty.tick(DT);
        }
        int asleepAfterSettle = pile.lastTick().ballsAsleep();
        List<Vect> settled = pile.balls().stream().map(BallView::position).toList();
        int block = 1_000;
        long pileNanos = 0;
        long emptyNanos = 0;
        int ticks = 0;
        for (; ticks < w.pileTicks(); ticks += block) {
            pileNanos += cpuOfBlock(pile, block);
            emptyNanos += cpuOfBlock(empty, block);
        }
        double moved = 0;
        for (int i = 0; i < settled.size(); i++) {
            moved = Math.max(moved, settled.get(i).minus(pile.balls().get(i).position()).length());
        }
        return new Pile(pile.balls().size(), asleepAfterSettle, pile.lastTick().ballsAsleep(), pileNanos / 1e3 / ticks,
                emptyNanos / 1e3 / ticks, moved);
    }

    private static long cpuOfBlock(Board board, int ticks) {
        long start = THREADS.getCurrentThreadCpuTime();
        for (int t = 0; t < ticks; t++) {
            board.tick(DT);
        }
        return THREADS.getCurrentThreadCpuTime() - start;
    }

    /**
     * Every shipped board (strictly loaded) and every file of the peer folder that loads something when its bad
     * lines are skipped, each ticked {@code ticks} times from load.
     */
    static Survey survey(Path shipped, Optional<Path> peers, int ticks) throws IOException {
        List<Surveyed> boards = new ArrayList<>();
        int seen = 0;
        for (NamedBoard named : boards(shipped, Optional.empty())) {
            boards.add(play(named, ticks));
        }
        if (peers.isPresent()) {
            for (Path file : files(peers.get(), "")) {
                seen++;
                LoadResult loaded = BoardFiles.loadSkippingBadLines(file);
                if (!loaded.keptNothing()) {
                    boards.add(play(new NamedBoard(String.valueOf(file.getFileName()), loaded.board()), ticks));
                }
            }
        }
        return new Survey(ticks, seen, boards);
    }

    private static Surveyed play(NamedBoard named, int ticks) {
        Board board = named.board();
        int balls = board.balls().size();
        long jams = 0;
        try {
            for (int t = 0; t < ticks; t++) {
                board.tick(DT);
                jams += board.lastTick().events().stream().filter(e -> e instanceof PlayEvent.Jammed).count();
            }
            return new Surveyed(named.name(), balls, board.guardsFired(), jams, Optional.empty());
        } catch (RuntimeException e) {
            return new Surveyed(named.name(), balls, board.guardsFired(), jams,
                    Optional.of("tick " + Math.round(board.time() / DT) + ": " + e));
        }
    }

    private static List<Path> files(Path dir, String suffix) throws IOException {
        try (Stream<Path> list = Files.list(dir)) {
            return list.filter(Files::isRegularFile).filter(p -> p.toString().endsWith(suffix)).sorted().toList();
        }
    }

    // ---------------------------------------------------------------- printing and CSV

    static void printRows(PrintStream out, List<Row> rows, Windows w) {
        out.println();
        out.printf(Locale.ROOT, "Steady state at 1/60 s: ticks %,d-%,d after a warm-up of ticks 0-%,d%s; each tick timed "
                        + "alone; guards: fired within the window%n", w.from(), w.to(), w.from(),
                !w.equals(Windows.FULL) ? " (quick run: shorter windows than the full run's 3,000-15,000)" : "");
        out.println("                                         ------- wall us ------- -------- CPU us -------");
        String format = "%-28s %6s %5s %4s %7s %7s %8s %7s %7s %7s %9s %9s %8s %9s %8s %6s %5s %6s %7s %5s %8s%n";
        out.printf(Locale.ROOT, format, "board", "gizmos", "balls", "warm", "mean", "p99", "max", "mean", "p99", "max",
                "B/tick", "coll/tick",
                "max coll", "zero/tick", "max zero", "asleep", "awake", "wedged", "pinched", "cap", "GCs (ms)");
        for (Row r : rows) {
            out.printf(Locale.ROOT, format, shortName(r.board()), r.gizmos(), r.balls(), r.warmPlays(), f1(r.meanUs()), f1(r.p99Us()),
                    f1(r.maxUs()), f1(r.cpuMeanUs()), f1(r.cpuP99Us()), f1(r.cpuMaxUs()),
                    String.format(Locale.ROOT, "%,.0f", r.bytesPerTick()), f2(r.meanCollisions()),
                    r.maxCollisions(), f2(r.meanZeroTime()), r.maxZeroTime(),
                    r.asleep(), r.awake(), r.guards().wedged(), r.guards().pinched(), r.guards().collisionCap(),
                    r.gcPauses() + " (" + r.gcMillis() + ")");
        }
        out.println("(warm: throw-away plays of a copy before the window, until the JIT compilers were quiet during one; "
                + "wall: each tick by System.nanoTime, the model's stage clocks on; CPU: the ticking thread's CPU time "
                + "of each tick, in a second run, the stage clocks off as in play; "
                + "B/tick: bytes the ticking thread allocated per tick of the window, in the second run; "
                + MANY_IN_PLAY + ": ticks " + IN_PLAY.from() + "-" + IN_PLAY.to() + " of a full run, while its balls fly; "
                + "asleep, awake: balls at the end; GCs: garbage collections "
                + "during the window and their total time)");
        out.println("Where the window's time goes: the slowest tick by CPU time, and each stage's share of the time the model's "
                + "stage clocks measured in the wall run (TickReport.stageNanos)");
        StringBuilder stageFormat = new StringBuilder("%-28s %20s");
        List<Object> header = new ArrayList<>(List.of("board", "slowest tick (coll)"));
        for (Stage stage : Stage.values()) {
            stageFormat.append(" %").append(stageLabel(stage).length()).append('s');
            header.add(stageLabel(stage));
        }
        String format2 = stageFormat.append("%n").toString();
        out.printf(Locale.ROOT, format2, header.toArray());
        for (Row r : rows) {
            long total = r.stageNanos().values().stream().mapToLong(Long::longValue).sum();
            List<Object> cells = new ArrayList<>(List.of(shortName(r.board()),
                    String.format(Locale.ROOT, "%,d (%d)", r.slowestTick(), r.slowestCollisions())));
            for (Stage stage : Stage.values()) {
                cells.add(String.format(Locale.ROOT, "%.0f%%", 100.0 * r.stageNanos().getOrDefault(stage, 0L) / total));
            }
            out.printf(Locale.ROOT, format2, cells.toArray());
        }
    }

    private static String stageLabel(Stage stage) {
        return switch (stage) {
            case FRICTION_AND_GRAVITY -> "1 gravity";
            case BALL_MOTION -> "2 motion";
            case COLLISION_DETECTION -> "3 detection";
            case COLLISION_RESOLUTION -> "4 resolution";
            case TRIGGERING -> "5 triggers";
            case REDRAWING -> "6 redraw";
        };
    }

    /** Peer file names are long (owner__repository__path); the table shows their last part. */
    static String shortName(String board) {
        int cut = board.lastIndexOf("__");
        return cut < 0 ? board : "peer " + board.substring(cut + 2);
    }

    static void printPile(PrintStream out, Pile p, Windows w) {
        out.println();
        out.printf(Locale.ROOT, "Sleeping pile: two squares on the floor with %d touching balls between them (rows of 8, 7, "
                + "6), settled %d ticks, against the same board with no balls; %,d ticks of each, in alternating blocks "
                + "of 1,000 timed by thread CPU time%s%n", p.balls(), w.pileSettle(), w.pileTicks(), quickNote(w, Windows.FULL.pileTicks()));
        out.printf(Locale.ROOT, "  asleep after settling %d of %d, at the end %d; farthest a ball moved while timed %s L%n",
                p.asleepAfterSettle(), p.balls(), p.asleepAtEnd(), e(p.moved()));
        out.printf(Locale.ROOT, "  pile %.3f CPU us per tick, no balls %.3f CPU us per tick: ratio %.2f%n",
                p.pileUs(), p.emptyUs(), p.ratio());
    }

    private static String quickNote(Windows w, int fullTicks) {
        return w.equals(Windows.FULL) ? "" : String.format(Locale.ROOT, " (quick run: the full run's is %,d)", fullTicks);
    }

    static void printSurvey(PrintStream out, Survey s, Windows w, int worst) {
        out.println();
        GuardCounts t = s.totals();
        List<Surveyed> firing = s.firing();
        out.printf(Locale.ROOT, "Guard survey: %,d ticks of each of %d boards (the shipped ones and the %s of %d peer files "
                        + "that load something with bad lines skipped)%s%n", s.ticks(), s.boards().size(),
                s.filesSeen() == 0 ? "none" : Integer.toString(s.boards().size() - shippedCount(s)), s.filesSeen(),
                quickNote(w, Windows.FULL.surveyTicks()));
        out.printf(Locale.ROOT, "  boards on which a guard fired: %d; totals: wedged %d, pinched %d, collision cap %d%n",
                firing.size(), t.wedged(), t.pinched(), t.collisionCap());
        out.printf(Locale.ROOT, "  jams (a flipper stalled by a ball it cannot squeeze out; physics, not a guard): %d on %d "
                + "boards%n", s.jams(), s.jamming());
        for (Surveyed b : firing.subList(0, Math.min(worst, firing.size()))) {
            out.printf(Locale.ROOT, "  %-80s balls %3d: wedged %d, pinched %d, cap %d%n", b.board(), b.balls(),
                    b.guards().wedged(), b.guards().pinched(), b.guards().collisionCap());
        }
        s.boards().stream().filter(b -> b.failure().isPresent())
                .forEach(b -> out.printf(Locale.ROOT, "  FAILED %s: %s%n", b.board(), b.failure().get()));
    }

    private static int shippedCount(Survey s) {
        return (int) s.boards().stream().filter(b -> !b.board().contains("__")).count();
    }

    static void writeRows(Path file, List<Row> rows) throws IOException {
        List<String> lines = new ArrayList<>();
        lines.add("board,gizmos,balls,from_tick,to_tick,warm_plays,wall_mean_us,wall_p99_us,wall_max_us,cpu_mean_us,cpu_p99_us,cpu_max_us,bytes_per_tick,collisions_per_tick,max_collisions,"
                + "zero_time_per_tick,max_zero_time,balls_asleep_end,balls_awake_end,guard_wedged,guard_pinched,guard_cap,"
                + "gc_count,gc_ms");
        for (Row r : rows) {
            lines.add(String.format(Locale.ROOT, "%s,%d,%d,%d,%d,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.0f,%.4f,%d,%.4f,%d,%d,%d,%d,%d,%d,%d,%d",
                    r.board(), r.gizmos(), r.balls(), r.from(), r.to(), r.warmPlays(), r.meanUs(), r.p99Us(), r.maxUs(), r.cpuMeanUs(),
                    r.cpuP99Us(), r.cpuMaxUs(), r.bytesPerTick(),
                    r.meanCollisions(), r.maxCollisions(), r.meanZeroTime(), r.maxZeroTime(), r.asleep(), r.awake(), r.guards().wedged(),
                    r.guards().pinched(), r.guards().collisionCap(), r.gcPauses(), r.gcMillis()));
        }
        Files.write(file, lines);
    }

    /** Per bin of {@link #BIN} ticks: the first tick, the mean and the max cost (us). */
    static void writeBins(Path file, long[] tickNanos) throws IOException {
        List<String> lines = new ArrayList<>();
        lines.add("first_tick,mean_us,max_us");
        for (Bin b : bins(tickNanos)) {
            lines.add(String.format(Locale.ROOT, "%d,%.3f,%.3f", b.firstTick(), b.meanUs(), b.maxUs()));
        }
        Files.write(file, lines);
    }

    record Bin(int firstTick, double meanUs, double maxUs) {
    }

    static List<Bin> bins(long[] tickNanos) {
        List<Bin> bins = new ArrayList<>();
        for (int first = 0; first + BIN <= tickNanos.length; first += BIN) {
            long sum = 0;
            long max = 0;
            for (int t = first; t < first + BIN; t++) {
                sum += tickNanos[t];
                max = Math.max(max, tickNanos[t]);
            }
            bins.add(new Bin(first, sum / 1e3 / BIN, max / 1e3));
        }
        return bins;
    }

    static void writePile(Path file, Pile p) throws IOException {
        Files.write(file, List.of("balls,asleep_after_settle,asleep_end,pile_cpu_us_per_tick,empty_cpu_us_per_tick,ratio,moved_L",
                String.format(Locale.ROOT, "%d,%d,%d,%.4f,%.4f,%.4f,%s", p.balls(), p.asleepAfterSettle(), p.asleepAtEnd(),
                        p.pileUs(), p.emptyUs(), p.ratio(), Double.toString(p.moved()))));
    }

    static void writeSurvey(Path file, Survey s) throws IOException {
        List<String> lines = new ArrayList<>();
        lines.add("board,balls,ticks,guard_wedged,guard_pinched,guard_cap,jams,failure");
        for (Surveyed b : s.boards()) {
            lines.add(String.format(Locale.ROOT, "%s,%d,%d,%d,%d,%d,%d,%s", b.board(), b.balls(), s.ticks(),
                    b.guards().wedged(), b.guards().pinched(), b.guards().collisionCap(), b.jams(),
                    b.failure().map(f -> '"' + f.replace("\"", "\"\"") + '"').orElse("")));
        }
        Files.write(file, lines);
    }

    private static String f1(double v) {
        return String.format(Locale.ROOT, "%.1f", v);
    }

    private static String f2(double v) {
        return String.format(Locale.ROOT, "%.2f", v);
    }

    private static String e(double v) {
        return String.format(Locale.ROOT, "%.1e", v);
    }
}
