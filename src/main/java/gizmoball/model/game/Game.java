package gizmoball.model.game;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.TickEvents;
import gizmoball.model.loop.TriggerSource;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.Deque;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.OptionalLong;

/**
 * The game in progress on one board, for 1 to {@link #MAX_PLAYERS} players taking turns ball by ball, moved on by the
 * board after each tick from that tick's play events, in the order they happened: a real hit on a gizmo scores its
 * points for the player whose ball is in play ({@link PlayEvent.Hit#isRealImpact()}), reaching the extra-ball score
 * gives that player one more ball, and a capture by a drain (or a sink) loses the ball. While other balls are still
 * on the board (a multiball) the lost one only leaves it; the last one ends the ball in play: saved if it drained
 * within the ball save of its launch (once a ball), else the next player with balls to come plays next, the ball
 * served into the launcher ({@link Playfield#serve}); when no player has one left the game is over. The balls to
 * come are counted when the first tick starts the game: the first player's are the board's balls per game less the
 * balls already on it. Nudges ({@link #nudged}) count toward the board's {@link Tilt}.
 *
 * <p>Its members that change it are public because the board is in another package; they are for the board only.
 * Views see a game as a {@link GameProgress}.
 */
public final class Game implements GameProgress {
    public static final int MAX_PLAYERS = 4;
    /**
     * The scoring hits a game lists at most ({@link #scoringHits}); those after are counted. A board of 200 balls among
     * bumpers scores some 40 hits a tick, and a list of every one grew by some 300 MB an hour; a game of a few balls,
     * scoring ten hits a second, lists an hour of play.
     */
    public static final int LISTED_SCORING_HITS = 100_000;

    private final Playfield field;
    private int players = 1;
    private boolean started;
    /** Each player's balls still to come, once started (not the one in play). */
    private int[] toCome = new int[1];
    private long[] scores = new long[1];
    private boolean[] extraBallGiven = new boolean[1];
    private int current;
    private boolean over;
    /** The board time the ball in play was launched, while its ball save can still apply. */
    private OptionalDouble launchedAt = OptionalDouble.empty();
    private boolean saveUsed;
    private boolean tilted;
    /** The board times of the recent nudges, oldest first. */
    private final Deque<Double> nudges = new ArrayDeque<>();
    private final List<ScoringHit> scoringHits = new ArrayList<>();
    private long unlistedScoringHits;
    private final List<Drain> drains = new ArrayList<>();
    private final List<KeyPress> keys = new ArrayList<>();
    private final List<Notice> notices = new ArrayList<>();

    /** For the board: a game not started yet on that board. */
    public Game(Playfield field) {
        this.field = field;
    }

    /** For the board: becomes a copy of {@code source}'s progress (a board copied mid-game goes on with it). */
    public void copyFrom(Game source) {
        players = source.players;
        started = source.started;
        toCome = source.toCome.clone();
        scores = source.scores.clone();
        extraBallGiven = source.extraBallGiven.clone();
        current = source.current;
        over = source.over;
        launchedAt = source.launchedAt;
        saveUsed = source.saveUsed;
        tilted = source.tilted;
        nudges.clear();
        nudges.addAll(source.nudges);
        scoringHits.clear();
        scoringHits.addAll(source.scoringHits);
        unlistedScoringHits = source.unlistedScoringHits;
        drains.clear();
        drains.addAll(source.drains);
        keys.clear();
        keys.addAll(source.keys);
        notices.clear();
        notices.addAll(source.notices);
    }

    /** For the board: back to a game not started, as on a board just made, for as many players as it had. */
    public void reset() {
        int had = players;
        copyFrom(new Game(field));
        setPlayers(had);
    }

    /**
     * For the board: the game is for that many players, 1 to {@link #MAX_PLAYERS}, before it starts.
     *
     * @throws IllegalArgumentException out of range
     * @throws IllegalStateException once the game has started
     */
    public void setPlayers(int count) {
        if (count < 1 || count > MAX_PLAYERS) {
            throw new IllegalArgumentException("a game is for 1 to " + MAX_PLAYERS + " players, not " + count);
        }
        if (started) {
            throw new IllegalStateException("the number of players is chosen before the game starts");
        }
        players = count;
        toCome = new int[count];
        scores = new long[count];
        extraBallGiven = new boolean[count];
    }

    /** For the board: the player pressed or released a key after {@code tick} ticks. */
    public void keyPressed(long tick, KeyPress.Motion motion, int keyCode) {
        keys.add(new KeyPress(tick, motion, keyCode));
    }

    /**
     * For the board: the player nudged after {@code tick} ticks. Returns true if that nudge tilted the game: the
     * board then lowers the flippers and drops the plungers' pulls.
     */
    public boolean nudged(long tick) {
        GameRules rules = field.rules();
        if (!rules.isGame() || over || tilted) {
            return false;
        }
        double now = field.time();
        nudges.addLast(now);
        while (nudges.getFirst() <= now - rules.tilt().seconds()) {
            nudges.removeFirst();
        }
        if (nudges.size() >= rules.tilt().nudges()) {
            tilted = true;
            notices.add(new Notice(tick, Notice.Kind.TILT, current));
            return true;
        }
        if (nudges.size() == rules.tilt().nudges() - 1) {
            notices.add(new Notice(tick, Notice.Kind.WARNING, current));
        }
        return false;
    }

    /** For the board: what the tick numbered {@code tick} did to the game. */
    public void afterTick(long tick, TickEvents events) {
        GameRules rules = field.rules();
        if (!started) {
            started = true;
            toCome[0] = Math.max(0, rules.ballsPerGame() - field.ballCount());
            Arrays.fill(toCome, 1, players, rules.ballsPerGame());
        }
        for (int i = 0; i < events.size(); i++) {
            if (events.isHit(i)) {
                if (PlayEvent.Hit.isRealImpact(events.speed(i))
                        && events.struck(i) instanceof TriggerSource.OfGizmo gizmo) {
                    scored(tick, rules, gizmo.gizmo(), rules.pointsOf(gizmo.gizmo(), events.kind(i)));
                }
                continue;
            }
            PlayEvent event = events.event(i);
            if (event instanceof PlayEvent.Fired fired && field.isLauncher(fired.absorber()) && !saveUsed) {
                launchedAt = OptionalDouble.of(field.time());
            } else if (event instanceof PlayEvent.Captured captured && rules.isDrain(captured.absorber()) && !over) {
                drains.add(new Drain(tick, captured.ball(), captured.absorber()));
                lost(tick, rules, Optional.of(captured.ball()));
            } else if (event instanceof PlayEvent.Sunk sunk && rules.isGame() && !over) {
                // Gone from the board already: lost as a drained ball is; the next, if any, is served.
                scored(tick, rules, sunk.sink(), rules.pointsOf(sunk.sink(), GizmoKind.SINK));
                drains.add(new Drain(tick, sunk.ball(), sunk.sink()));
                lost(tick, rules, Optional.empty());
            }
        }
        if (tilted && field.freeBallCount() == 0) {
            tilted = false;   // every ball is held: the tilted one came to rest in an absorber that is no drain
        }
    }

    private void scored(long tick, GameRules rules, String gizmo, int points) {
        if (points == 0 || over || tilted) {
            return;
        }
        scores[current] += points;
        if (scoringHits.size() < LISTED_SCORING_HITS) {
            scoringHits.add(new ScoringHit(tick, gizmo, points));
        } else {
            unlistedScoringHits++;
        }
        if (rules.isGame() && !extraBallGiven[current] && rules.extraBallAt().isPresent()
                && scores[current] >= rules.extraBallAt().getAsLong()) {
            extraBallGiven[current] = true;
            toCome[current]++;
            notices.add(new Notice(tick, Notice.Kind.EXTRA_BALL, current));
        }
    }

    /**
     * A ball was lost: {@code drained} is held by a drain, or empty when a sink took it off the board. The last ball on
     * the board ends the ball in play, unless its ball save gives it back.
     */
    private void lost(long tick, GameRules rules, Optional<String> drained) {
        if (field.ballCount() > (drained.isPresent() ? 1 : 0)) {
            drained.ifPresent(field::removeBall);   // a multiball goes on with the others
            return;
        }
        boolean inSave = rules.ballSaveSeconds() > 0 && launchedAt.isPresent() && field.time() - launchedAt.getAsDouble() <= rules.ballSaveSeconds();
        launchedAt = OptionalDouble.empty();
        if (inSave && !tilted && !saveUsed && field.serve(drained)) {
            saveUsed = true;
            notices.add(new Notice(tick, Notice.Kind.BALL_SAVED, current));
            return;
        }
        tilted = false;
        saveUsed = false;
        nudges.clear();
        for (int step = 1; step <= players; step++) {
            int next = (current + step) % players;
            if (toCome[next] > 0 && field.serve(drained)) {
                toCome[next]--;
                if (next != current) {
                    notices.add(new Notice(tick, Notice.Kind.NEXT_PLAYER, next));
                }
                current = next;
                return;
            }
        }
        drained.ifPresent(field::removeBall);
        over = true;
    }

    @Override
    public boolean isGame() {
        return field.rules().isGame();
    }

    @Override
    public int players() {
        return players;
    }

    @Override
    public int currentPlayer() {
        return current;
    }

    @Override
    public long score() {
        return Arrays.stream(scores).sum();
    }

    @Override
    public long score(int player) {
        return scores[player];
    }

    @Override
    public int ballsLeft() {
        int balls = field.ballCount();
        if (!started) {
            return Math.max(balls, field.rules().ballsPerGame()) + (players - 1) * field.rules().ballsPerGame();
        }
        return balls + Arrays.stream(toCome).sum();
    }

    @Override
    public int ballsLeft(int player) {
        int own = started ? toCome[player] : field.rules().ballsPerGame() - (player == 0 ? 1 : 0);
        return own + (player == current && !over ? 1 : 0);
    }

    @Override
    public boolean isOver() {
        return over;
    }

    @Override
    public boolean isTilted() {
        return tilted;
    }

    @Override
    public OptionalLong extraBallTick() {
        return notices.stream().filter(n -> n.kind() == Notice.Kind.EXTRA_BALL).mapToLong(Notice::tick).findFirst();
    }

    @Override
    public List<ScoringHit> scoringHits() {
        return Collections.unmodifiableList(scoringHits);
    }

    @Override
    public long unlistedScoringHits() {
        return unlistedScoringHits;
    }

    @Override
    public List<Drain> drains() {
        return Collections.unmodifiableList(drains);
    }

    @Override
    public List<KeyPress> keys() {
        return Collections.unmodifiableList(keys);
    }

    @Override
    public List<Notice> notices() {
        return Collections.unmodifiableList(notices);
    }
}
