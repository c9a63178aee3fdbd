package gizmoball.controller;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Issue 23, items 4 and 5: the chooser's board files and the file a typed name means, without a window. */
class BoardFileFilterTest {
    private final BoardFileFilter filter = new BoardFileFilter();

    @Test
    void theBoardFilesOfPeersAndNamesWithoutAnEndingAreShown() {
        for (String name : new String[] {"a.txt", "b.gizmo", "c.gb", "d.giz", "e.gzm", "F.GB", "saveFile", ".hidden"}) {
            assertThat(filter.accept(new File(name))).as(name).isTrue();
        }
    }

    @Test
    void otherFilesAreNot() {
        for (String name : new String[] {"shot.png", "notes.md", "world.g3d", "x.txt~"}) {
            assertThat(filter.accept(new File(name))).as(name).isFalse();
        }
    }

    @Test
    void foldersAreShownToWalkThrough(@TempDir Path dir) throws Exception {
        assertThat(filter.accept(Files.createDirectory(dir.resolve("boards.d")).toFile())).isTrue();
    }

    @Test
    void aTypedNameMeansTheFileSaveAsWroteForIt(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("xyz.txt"), "Gravity 25.0\n");

        assertThat(BoardFileCommands.existing(dir.resolve("xyz"))).isEqualTo(dir.resolve("xyz.txt"));
    }

    @Test
    void aNameThatExistsAsTypedIsTakenAsTyped(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("xyz"), "Gravity 25.0\n");
        Files.writeString(dir.resolve("xyz.txt"), "Gravity 25.0\n");

        assertThat(BoardFileCommands.existing(dir.resolve("xyz"))).isEqualTo(dir.resolve("xyz"));
        assertThat(BoardFileCommands.existing(dir.resolve("none"))).isEqualTo(dir.resolve("none"));
    }
}
