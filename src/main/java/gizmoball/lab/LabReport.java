package gizmoball.lab;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import java.util.Locale;

/**
 * The lab's summary of a board, as its JSON report says it (docs/running.md, "The board lab"): how it was played,
 * each player's figures, and what the flippers are worth (the autoplayer's mean score over the idle player's).
 *
 * @param autoplayerOverIdle the autoplayer's mean score over the idle player's; null when the idle player scores
 *                           nothing
 * @param verdict            whether the flippers matter, in words
 */
public record LabReport(String board, int gamesPerPlayer, double gameCapSeconds, double tickSeconds,
                        Double autoplayerOverIdle, String verdict, PlayerReport autoplayer, PlayerReport idle) {
    /** The autoplayer scoring this many times the idle player's mean is a game of skill (issue 36's target). */
    public static final double MATTERS = 2;
    /** Below this many times, the flippers change next to nothing. */
    public static final double MATTERS_A_LITTLE = 1.2;

    private static final Gson GSON = new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create();

    static LabReport of(String board, LabSettings settings, PlayerReport autoplayer, PlayerReport idle) {
        double auto = autoplayer.score().mean();
        double still = idle.score().mean();
        Double ratio = still > 0 ? auto / still : null;
        String verdict;
        if (auto == 0 && still == 0) {
            verdict = "nothing scores";
        } else if (ratio == null || ratio >= MATTERS) {
            verdict = "the flippers matter";
        } else if (ratio >= MATTERS_A_LITTLE) {
            verdict = "the flippers matter a little";
        } else {
            verdict = "the flippers do not matter";
        }
        return new LabReport(board, settings.games(), settings.gameCapSeconds(), settings.dt(), ratio, verdict,
                autoplayer, idle);
    }

    /** What a heat map of the autoplayer's games says it shows. */
    public String heatMapCaption() {
        return String.format(Locale.ROOT, "%s, autoplayer, %d games", board, gamesPerPlayer);
    }

    public String toJson() {
        return GSON.toJson(this) + "\n";
    }

    /** The verdict with the two mean scores and their ratio: "the flippers matter (autoplayer mean score ...)". */
    public String verdictLine() {
        String ratio = autoplayerOverIdle == null ? "" : String.format(Locale.ROOT, " = %.2fx", autoplayerOverIdle);
        return String.format(Locale.ROOT, "%s (autoplayer mean score %.0f / idle %.0f%s)", verdict,
                autoplayer.score().mean(), idle.score().mean(), ratio);
    }

    /** One line for people: the verdict line, how long a ball lasts, and the games played. */
    public String summaryLine() {
        return String.format(Locale.ROOT, "%s: %s; a ball lasts %.1f s (autoplayer), %.1f s (idle); %d games each",
                board, verdictLine(), autoplayer.secondsPerBall().mean(), idle.secondsPerBall().mean(),
                gamesPerPlayer);
    }
}
