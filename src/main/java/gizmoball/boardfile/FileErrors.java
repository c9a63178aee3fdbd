package gizmoball.boardfile;

import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Optional;

/**
 * What went wrong reading or saving a board file, in the player's words. The one home of that wording, so
 * the window and the headless runner say the same thing. The JDK's file-system exceptions carry only a path
 * as their message (often the temporary file of a save, which the player never named), so the wording comes
 * from the kind of failure and the state of the folder instead.
 */
public final class FileErrors {

    private FileErrors() {
    }

    /** E.g. "cannot save /tmp/no-such-dir/b.txt: the folder /tmp/no-such-dir does not exist". */
    public static String cannotSave(Path file, IOException e) {
        return "cannot save " + file + ": " + saveReason(file, e);
    }

    /** E.g. "cannot read /tmp/b.txt: there is no such file". */
    public static String cannotRead(Path file, IOException e) {
        return "cannot read " + file + ": " + readReason(file, e);
    }

    /** Why saving {@code file} failed: "permission denied", "read-only file system", ... */
    public static String saveReason(Path file, IOException e) {
        if (Files.isDirectory(file)) {
            return "it is a folder";
        }
        return folderProblem(file, e).orElseGet(() -> e instanceof NoSuchFileException
                // The folder is there but refuses new files without saying why, as /proc does.
                ? "the folder " + folderOf(file) + " does not take new files"
                : common(e));
    }

    /** Why reading {@code file} failed: "there is no such file", "permission denied", "it is not text", ... */
    public static String readReason(Path file, IOException e) {
        if (Files.isDirectory(file)) {
            return "it is a folder";
        }
        if (e instanceof CharacterCodingException) {
            // The JDK says only "Input length = 1": the file holds bytes that are no UTF-8 text (an image, say).
            return "it is not text (it holds bytes that are not UTF-8)";
        }
        return folderProblem(file, e).orElseGet(() -> e instanceof NoSuchFileException
                ? "there is no such file"
                : common(e));
    }

    private static Optional<String> folderProblem(Path file, IOException e) {
        Path folder = folderOf(file);
        if (e instanceof AccessDeniedException || !(e instanceof FileSystemException)) {
            return Optional.empty();
        }
        if (!Files.exists(folder)) {
            return Optional.of("the folder " + folder + " does not exist");
        }
        if (!Files.isDirectory(folder)) {
            return Optional.of(folder + " is not a folder");
        }
        return Optional.empty();
    }

    private static String common(IOException e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof FileSystemException fileSystem && fileSystem.getReason() != null) {
            return lowerFirst(fileSystem.getReason());
        }
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
    }

    private static Path folderOf(Path file) {
        Path absolute = file.toAbsolutePath();
        return absolute.getParent() == null ? absolute : absolute.getParent();
    }

    private static String lowerFirst(String s) {
        return s.isEmpty() ? s : s.substring(0, 1).toLowerCase(Locale.ROOT) + s.substring(1);
    }
}
