package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import gizmoball.model.Board;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The wording of read and save failures, from real failures where this machine can make them. */
class FileErrorsTest {
    @TempDir
    Path directory;

    private static IOException saving(Path file) {
        return catchThrowableOfType(() -> BoardFiles.save(new Board(), file), IOException.class);
    }

    @Test
    void savingIntoAMissingFolderNamesTheFolderNotTheTemporaryFile() {
        Path file = directory.resolve("no-such-dir").resolve("b.txt");
        assertThat(FileErrors.cannotSave(file, saving(file)))
                .isEqualTo("cannot save " + file + ": the folder " + directory.resolve("no-such-dir")
                        + " does not exist");
    }

    @Test
    void savingUnderAPlainFileSaysItIsNoFolder() throws IOException {
        Path plain = Files.writeString(directory.resolve("plain"), "x");
        Path file = plain.resolve("b.txt");
        assertThat(FileErrors.saveReason(file, saving(file))).isEqualTo(plain + " is not a folder");
    }

    @Test
    void savingOverAFolderSaysSo() throws IOException {
        Path folder = Files.createDirectory(directory.resolve("b.txt"));
        Files.writeString(folder.resolve("inside"), "x");
        assertThat(FileErrors.saveReason(folder, saving(folder))).isEqualTo("it is a folder");
    }

    @Test
    void aFolderThatRefusesNewFilesWithoutAReasonIsNamed() {
        // /proc answers "no such file" to creating a file in it, which would read as if the folder were missing.
        Path file = Path.of("/proc/b.txt");
        IOException e = saving(file);
        assertThat(e).as("this machine lets a file be created in /proc").isNotNull();
        assertThat(FileErrors.saveReason(file, e)).isIn("the folder /proc does not take new files",
                "permission denied");
    }

    @Test
    void theOperatingSystemsReasonIsPassedOnInLowerCase() {
        // What the JDK throws for EROFS: a FileSystemException whose reason is strerror's text.
        IOException readOnly = new FileSystemException("/media/cd/.b.txt.1.tmp", null, "Read-only file system");
        assertThat(FileErrors.saveReason(directory.resolve("b.txt"), readOnly)).isEqualTo("read-only file system");
    }

    @Test
    void permissionDenied() {
        IOException denied = new AccessDeniedException("/root/.b.txt.1.tmp");
        assertThat(FileErrors.cannotSave(Path.of("/root/b.txt"), denied))
                .isEqualTo("cannot save /root/b.txt: permission denied");
    }

    @Test
    void readingAMissingFile() throws IOException {
        Path file = directory.resolve("none.txt");
        IOException e = catchThrowableOfType(() -> BoardFiles.load(file), IOException.class);
        assertThat(FileErrors.cannotRead(file, e)).isEqualTo("cannot read " + file + ": there is no such file");
    }

    /** Issue 40 item 8: a file that is not text says so, not the JDK's "Input length = 1". */
    @Test
    void readingAFileThatIsNotText() {
        Path file = directory.resolve("junk.json");
        assertThat(FileErrors.cannotRead(file, new java.nio.charset.MalformedInputException(1)))
                .isEqualTo("cannot read " + file + ": it is not text (it holds bytes that are not UTF-8)");
    }
}
