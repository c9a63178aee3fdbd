package gizmoball.replay;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import gizmoball.model.Board;
import gizmoball.model.game.Drain;
import gizmoball.model.game.GameProgress;
import gizmoball.model.game.Notice;
import gizmoball.model.game.ScoringHit;
import java.util.List;
import java.util.stream.IntStream;

/**
 * The JSON summary of a game (the headless runner's {@code --report}): the ticks run, score, balls left, whether the
 * game is over, the tick of each drain, every scoring hit (tick, gizmo, points) up to
 * {@link gizmoball.model.game.Game#LISTED_SCORING_HITS} and how many more there were, the players and each one's
 * score, and the game's notices (warnings, tilts, balls saved, extra balls, turns).
 */
public record GameReport(long ticks, long score, int ballsLeft, boolean gameOver, boolean sandbox,
                         Long extraBallTick, List<Drain> drains, List<ScoringHit> scoringHits,
                         long unlistedScoringHits, int players, List<Long> playerScores, List<Notice> notices) {
    private static final Gson GSON = new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create();

    public static GameReport of(Board board) {
        GameProgress game = board.game();
        return new GameReport(board.ticks(), game.score(), game.ballsLeft(), game.isOver(), !game.isGame(),
                game.extraBallTick().isPresent() ? game.extraBallTick().getAsLong() : null,
                List.copyOf(game.drains()), List.copyOf(game.scoringHits()), game.unlistedScoringHits(), game.players(),
                IntStream.range(0, game.players()).mapToObj(game::score).toList(), List.copyOf(game.notices()));
    }

    public String toJson() {
        return GSON.toJson(this) + "\n";
    }
}
