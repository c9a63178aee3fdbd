package gizmoball.boardfile;

import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The known word a misspelt one was most likely meant to be: the nearest by edits (a letter added, dropped,
 * changed, or two neighbours swapped; letter case ignored), if it is near enough to be a slip of the fingers: one
 * edit in a short word, two in a word of five letters or more.
 */
final class NearestWord {
    private static final int LONG_WORD = 5;

    private NearestWord() {
    }

    static Optional<String> among(String word, List<String> known) {
        String typed = word.toLowerCase(Locale.ROOT);
        int allowed = typed.length() >= LONG_WORD ? 2 : 1;
        return known.stream()
                .filter(k -> distance(typed, k.toLowerCase(Locale.ROOT)) <= allowed)
                .min(Comparator.comparingInt(k -> distance(typed, k.toLowerCase(Locale.ROOT))));
    }

    /** The optimal string alignment distance: insertions, deletions, substitutions and adjacent swaps. */
    static int distance(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); i++) {
            d[i][0] = i;
        }
        for (int j = 0; j <= b.length(); j++) {
            d[0][j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            for (int j = 1; j <= b.length(); j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                d[i][j] = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
                }
            }
        }
        return d[a.length()][b.length()];
    }
}
