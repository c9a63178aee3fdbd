package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AtomicFileWriterTest {
    @TempDir
    Path directory;

    @Test
    void createsAndReplacesTheTarget() throws IOException {
        Path target = directory.resolve("board.txt");
        AtomicFileWriter.write(target, out -> out.write("first\n"));
        AtomicFileWriter.write(target, out -> out.write("second\n"));
        assertThat(Files.readString(target)).isEqualTo("second\n");
        assertThat(filesIn(directory)).containsExactly(target);
    }

    @Test
    void aWriterFailingMidWayLeavesTheOldFileIntactAndNoTemporaryFile() throws IOException {
        Path target = directory.resolve("board.txt");
        Files.writeString(target, "Square S 1 2\n", StandardCharsets.UTF_8);

        assertThatThrownBy(() -> AtomicFileWriter.write(target, out -> {
            out.write("Circle C 3 4\n".repeat(10_000));   // more than any buffer, so part of it reaches the disk
            throw new IOException("disk full");
        })).isInstanceOf(IOException.class).hasMessage("disk full");

        assertThat(Files.readString(target)).isEqualTo("Square S 1 2\n");
        assertThat(filesIn(directory)).containsExactly(target);
    }

    @Test
    void aRuntimeFailureMidWayAlsoLeavesTheOldFileIntact() throws IOException {
        Path target = directory.resolve("board.txt");
        Files.writeString(target, "old\n");
        assertThatThrownBy(() -> AtomicFileWriter.write(target, out -> {
            out.write("new");
            throw new IllegalStateException("bug in the writer");
        })).isInstanceOf(IllegalStateException.class);
        assertThat(Files.readString(target)).isEqualTo("old\n");
        assertThat(filesIn(directory)).containsExactly(target);
    }

    @Test
    void aMissingDirectoryFailsWithoutCreatingAnything() {
        Path target = directory.resolve("no-such-directory").resolve("board.txt");
        assertThatThrownBy(() -> AtomicFileWriter.write(target, out -> out.write("x")))
                .isInstanceOf(IOException.class);
        assertThat(directory.resolve("no-such-directory")).doesNotExist();
    }

    private static List<Path> filesIn(Path directory) throws IOException {
        try (Stream<Path> files = Files.list(directory)) {
            return files.toList();
        }
    }

    @Test
    void savingOverAFileKeepsItsPermissionBits() throws IOException {
        for (String mode : List.of("rw-r--r--", "rw-r-----", "rw-------", "rwxrwxr-x")) {
            Path target = directory.resolve("board-" + mode + ".txt");
            Files.writeString(target, "old\n");
            Files.setPosixFilePermissions(target, PosixFilePermissions.fromString(mode));

            AtomicFileWriter.write(target, out -> out.write("new\n"));

            assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(target))).isEqualTo(mode);
            assertThat(Files.readString(target)).isEqualTo("new\n");
        }
    }

    @Test
    void aNewFileGetsThePermissionsAnyOtherProgramWouldGiveIt() throws IOException {
        // The JVM cannot read the umask; a file created the ordinary way shows what it gives.
        Path ordinary = directory.resolve("ordinary.txt");
        try (Writer w = Files.newBufferedWriter(ordinary)) {
            w.write("x");
        }
        Path target = directory.resolve("board.txt");

        AtomicFileWriter.write(target, out -> out.write("new\n"));

        assertThat(Files.getPosixFilePermissions(target)).isEqualTo(Files.getPosixFilePermissions(ordinary));
    }
}
