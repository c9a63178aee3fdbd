package gizmoball.model.game;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.TriggerSource;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.OptionalLong;

/**
 * The game in progress on one board, moved on by the board after each tick from that tick's play events, in the
 * order they happened: a real hit on a gizmo scores its points ({@link PlayEvent.Hit#isRealImpact()}), reaching the
 * extra-ball score once gives one more ball, and a capture by a drain loses the ball. A drained ball stays in the
 * drain as the next ball while balls are still to come (the drain's key launches it), else it leaves the board;
 * when no ball is left the game is over. The balls to come are counted when the first tick starts the game: the
 * board's balls per game less the balls already on it.
 *
 * <p>Its members that change it are public because the board is in another package; they are for the board only.
 * Views see a game as a {@link GameProgress}.
 */
public final class Game implements GameProgress {
    private final Playfield field;
    private boolean started;
    /** The balls still to come, once started. */
    private int toCome;
    private long score;
    private boolean over;
    private OptionalLong extraBallTick = OptionalLong.empty();
    private final List<ScoringHit> scoringHits = new ArrayList<>();
    private final List<Drain> drains = new ArrayList<>();
    private final List<KeyPress> keys = new ArrayList<>();

    /** For the board: a game not started yet on that board. */
    public Game(Playfield field) {
        this.field = field;
    }

    /** For the board: becomes a copy of {@code source}'s progress (a board copied mid-game goes on with it). */
    public void copyFrom(Game source) {
        started = source.started;
        toCome = source.toCome;
        score = source.score;
        over = source.over;
        extraBallTick = source.extraBallTick;
        scoringHits.clear();
        scoringHits.addAll(source.scoringHits);
        drains.clear();
        drains.addAll(source.drains);
        keys.clear();
        keys.addAll(source.keys);
    }

    /** For the board: back to a game not started, as on a board just made. */
    public void reset() {
        copyFrom(new Game(field));
    }

    /** For the board: the player pressed or released a key after {@code tick} ticks. */
    public void keyPressed(long tick, KeyPress.Motion motion, int keyCode) {
        keys.add(new KeyPress(tick, motion, keyCode));
    }

    /** For the board: what the tick numbered {@code tick} did to the game. */
    public void afterTick(long tick, List<PlayEvent> events) {
        GameRules rules = field.rules();
        if (!started) {
            started = true;
            toCome = Math.max(0, rules.ballsPerGame() - field.ballCount());
        }
        for (PlayEvent event : events) {
            if (event instanceof PlayEvent.Hit hit && hit.isRealImpact() && hit.struck() instanceof TriggerSource.OfGizmo gizmo) {
                scored(tick, rules, gizmo.gizmo(), rules.pointsOf(gizmo.gizmo(), hit.kind()));
            } else if (event instanceof PlayEvent.Captured captured && rules.isDrain(captured.absorber()) && !over) {
                drained(tick, captured);
            } else if (event instanceof PlayEvent.Sunk sunk && rules.isGame() && !over) {
                // Gone from the board already: lost as a drained ball is; the next, if any, waits in a drain.
                scored(tick, rules, sunk.sink(), rules.pointsOf(sunk.sink(), GizmoKind.SINK));
                drains.add(new Drain(tick, sunk.ball(), sunk.sink()));
                if (toCome > 0 && field.serveNextBall()) {
                    toCome--;
                }
                over = field.ballCount() == 0;
            }
        }
    }

    private void scored(long tick, GameRules rules, String gizmo, int points) {
        if (points == 0 || over) {
            return;
        }
        score += points;
        scoringHits.add(new ScoringHit(tick, gizmo, points));
        if (rules.isGame() && extraBallTick.isEmpty() && rules.extraBallAt().isPresent()
                && score >= rules.extraBallAt().getAsLong()) {
            extraBallTick = OptionalLong.of(tick);
            toCome++;
        }
    }

    private void drained(long tick, PlayEvent.Captured captured) {
        drains.add(new Drain(tick, captured.ball(), captured.absorber()));
        if (toCome > 0) {
            toCome--;
        } else {
            field.removeBall(captured.ball());
            over = field.ballCount() == 0;
        }
    }

    @Override
    public boolean isGame() {
        return field.rules().isGame();
    }

    @Override
    public long score() {
        return score;
    }

    @Override
    public int ballsLeft() {
        int balls = field.ballCount();
        return balls + (started ? toCome : Math.max(0, field.rules().ballsPerGame() - balls));
    }

    @Override
    public boolean isOver() {
        return over;
    }

    @Override
    public OptionalLong extraBallTick() {
        return extraBallTick;
    }

    @Override
    public List<ScoringHit> scoringHits() {
        return Collections.unmodifiableList(scoringHits);
    }

    @Override
    public List<Drain> drains() {
        return Collections.unmodifiableList(drains);
    }

    @Override
    public List<KeyPress> keys() {
        return Collections.unmodifiableList(keys);
    }
}
