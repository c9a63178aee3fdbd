package gizmoball.boardfile;

import gizmoball.model.Board;
import java.util.ArrayList;
import java.util.List;

/**
 * What a save of an edited board writes over an authored text, and what of that text it would remove beyond the
 * lines of the things edited away, for the question asked before saving over the file.
 *
 * @param text  the file's new text
 * @param board the canonical commands of the board saved, for the save after this one
 */
public record SavePlan(String text, LostLines lost, List<Command> board) {
    public SavePlan {
        board = List.copyOf(board);
    }

    /** The canonical form of {@code board}, for a new board and the headless runner: nothing to lose. */
    public static SavePlan canonical(Board board) {
        return new SavePlan(BoardWriter.toText(board), LostLines.NONE, BoardWriter.commands(board));
    }

    /** The text as written, which the next save starts from. */
    public AuthoredText saved() {
        return AuthoredText.written(text, board);
    }

    /**
     * Lines of the file a save would remove that are no line of a thing edited away: lines the load left out, and
     * the comments and blank lines of a file whose edited board cannot be written around them.
     */
    public record LostLines(int badLines, int comments, int blankLines) {
        public static final LostLines NONE = new LostLines(0, 0, 0);

        public int total() {
            return badLines + comments + blankLines;
        }

        /** "2 bad lines", "1 bad line, 6 comments and 7 blank lines". */
        public String describe() {
            List<String> parts = new ArrayList<>();
            count(parts, badLines, "bad line");
            count(parts, comments, "comment");
            count(parts, blankLines, "blank line");
            if (parts.size() < 2) {
                return parts.isEmpty() ? "no lines" : parts.get(0);
            }
            return String.join(", ", parts.subList(0, parts.size() - 1)) + " and " + parts.get(parts.size() - 1);
        }

        private static void count(List<String> parts, int count, String what) {
            if (count > 0) {
                parts.add(count + " " + what + (count == 1 ? "" : "s"));
            }
        }
    }
}
