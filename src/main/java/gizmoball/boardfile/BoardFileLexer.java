package gizmoball.boardfile;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;

/**
 * Splits board-file text into numbered command lines and whitespace-separated words.
 * Tolerates what real files contain: CR LF (even CR CR LF) line ends, a byte-order mark,
 * blank lines, {@code #} comment lines, leading, trailing and repeated whitespace, no final newline. A line that
 * starts with {@code #@} and a letter is no comment to us: it is one of our additions to the format
 * ({@link CommandWord#OURS}), which other implementations skip as the comment it looks like.
 */
final class BoardFileLexer {
    private static final Pattern WHITESPACE = Pattern.compile("\\s+");
    private static final char BYTE_ORDER_MARK = '\uFEFF';

    private BoardFileLexer() {
    }

    /** The lines that carry a command, with their 1-based numbers in the file; blank and comment lines dropped. */
    static List<SourceLine> commandLines(String content) {
        String text = !content.isEmpty() && content.charAt(0) == BYTE_ORDER_MARK ? content.substring(1) : content;
        // Only LF ends a line: a CR is whitespace, so CR LF and the CR CR LF of some old writers count as
        // one line each and line numbers match what an editor shows.
        String[] raw = text.split("\n", -1);
        List<SourceLine> lines = new ArrayList<>();
        for (int i = 0; i < raw.length; i++) {
            String line = raw[i].replace("\r", "");
            String stripped = line.strip();
            if (!stripped.isEmpty() && (!stripped.startsWith("#") || isOurs(stripped))) {
                lines.add(new SourceLine(i + 1, line));
            }
        }
        return lines;
    }

    /**
     * {@code #@Word ...}: a command of ours (an unknown word is then an error of its line, as an unknown command is);
     * {@code #@ text} and any other {@code #} line are comments.
     */
    private static boolean isOurs(String stripped) {
        return stripped.startsWith(CommandWord.OURS) && stripped.length() > CommandWord.OURS.length()
                && Character.isLetter(stripped.charAt(CommandWord.OURS.length()));
    }

    static List<String> words(String line) {
        String stripped = line.strip();
        return stripped.isEmpty() ? List.of() : List.of(WHITESPACE.split(stripped));
    }
}
