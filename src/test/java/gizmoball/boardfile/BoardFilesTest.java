package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.TriggerSource;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class BoardFilesTest {
    @TempDir
    Path directory;

    private static Board sampleBoard() {
        Board board = new Board();
        board.addGizmo(GizmoKind.TRIANGLE, "T", 3, 4);
        board.rotate("T");
        board.rotate("T");
        board.addGizmo(GizmoKind.RIGHT_FLIPPER, "RF", 10, 10);
        board.addAbsorber("A", 0, 19, 20, 20);
        board.addBall("B", 5.5, 2.25, -1.5, 0.125);
        board.connect(TriggerSource.gizmo("T"), "RF");
        board.connect(TriggerSource.OUTER_WALLS, "A");
        board.bindKey(32, KeyEdge.DOWN, "A");
        board.setGravity(12.5);
        board.setFriction(0.5, 0.0);
        return board;
    }

    @Test
    void writesTheCanonicalForm() {
        assertThat(BoardFiles.toText(sampleBoard())).isEqualTo("""
                Triangle T 3 4
                RightFlipper RF 10 10
                Absorber A 0 19 20 20
                Rotate T
                Rotate T
                Ball B 5.5 2.25 -1.5 0.125
                Connect T RF
                Connect OuterWalls A
                KeyConnect key 32 down A
                Gravity 12.5
                Friction 0.5 0.0
                """);
    }

    @Test
    void savesAndLoadsAFile() throws IOException, BoardFileException {
        Path file = directory.resolve("board.txt");
        Board board = sampleBoard();
        BoardFiles.save(board, file);
        assertThat(BoardContents.of(BoardFiles.load(file))).isEqualTo(BoardContents.of(board));
        assertThat(BoardFiles.loadSkippingBadLines(file).skippedLines()).isEmpty();
    }

    @Test
    void errorsNameTheFile() throws IOException {
        Path file = directory.resolve("bad.txt");
        Files.writeString(file, "Square S 1 1\nSquare S 2 2\n");
        assertThatThrownBy(() -> BoardFiles.load(file)).isInstanceOf(BoardFileException.class)
                .hasMessageContaining(file + ":2: name S is already used: Square S 2 2");
    }

    @Test
    void aMissingFileIsAnIoError() {
        assertThatThrownBy(() -> BoardFiles.load(directory.resolve("none.txt"))).isInstanceOf(IOException.class);
    }

    @Test
    void aFailedSaveLeavesTheOldFileAndNoLitter() throws IOException {
        // A non-empty directory cannot be replaced by a file: the final rename fails after the content is written.
        Path target = directory.resolve("board.txt");
        Files.createDirectory(target);
        Path inside = Files.writeString(target.resolve("keep.txt"), "kept");

        assertThatThrownBy(() -> BoardFiles.save(sampleBoard(), target)).isInstanceOf(IOException.class);

        assertThat(Files.readString(inside)).isEqualTo("kept");
        try (Stream<Path> files = Files.list(directory)) {
            assertThat(files.toList()).isEqualTo(List.of(target));
        }
    }
}
