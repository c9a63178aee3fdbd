package gizmoball.boardfile;

import gizmoball.model.Board;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Loading and saving board files (format: docs/board-files.md). Loading never touches the caller's board:
 * it returns a new one, which the caller installs with {@link Board#replaceContents}.
 */
public final class BoardFiles {

    private BoardFiles() {
    }

    /** The board in the file, only if every line is good; otherwise every bad line is reported. */
    public static Board load(Path file) throws IOException, BoardFileException {
        return BoardLoader.load(file.toString(), read(file));
    }

    /** The board in the file without its bad lines, and exactly which lines were left out and why. */
    public static LoadResult loadSkippingBadLines(Path file) throws IOException {
        return BoardLoader.loadSkippingBadLines(file.toString(), read(file));
    }

    /** As {@link #load(Path)} for text already in memory; {@code source} names it in error reports. */
    public static Board load(String source, String text) throws BoardFileException {
        return BoardLoader.load(source, text);
    }

    /** As {@link #loadSkippingBadLines(Path)} for text already in memory. */
    public static LoadResult loadSkippingBadLines(String source, String text) {
        return BoardLoader.loadSkippingBadLines(source, text);
    }

    /** The board in canonical form (what {@link #save} writes). */
    public static String toText(Board board) {
        return BoardWriter.toText(board);
    }

    /** Writes the canonical form; if the write fails the file that was there is left untouched. */
    public static void save(Board board, Path file) throws IOException {
        String text = toText(board);
        AtomicFileWriter.write(file, out -> out.write(text));
    }

    /**
     * Writes the text of a save over an authored text (see {@link AuthoredText#saving}), unless the file already
     * holds exactly that text: a board saved unchanged leaves its file alone. If the write fails the file that was
     * there is left untouched. Returns whether anything was written.
     */
    public static boolean save(SavePlan plan, Path file) throws IOException {
        if (Files.isRegularFile(file) && read(file).equals(plan.text())) {
            return false;
        }
        AtomicFileWriter.write(file, out -> out.write(plan.text()));
        return true;
    }

    private static String read(Path file) throws IOException {
        // Undecodable bytes become U+FFFD and then fail as a bad line, with its number, instead of the whole file.
        return new String(Files.readAllBytes(file), StandardCharsets.UTF_8);
    }
}
