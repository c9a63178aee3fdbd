package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.gizmo.AcceleratorView;
import gizmoball.model.gizmo.GizmoKind;
import org.junit.jupiter.api.Test;

/**
 * The extension gizmos in files: ours are written {@code #@Sink}, {@code #@Accelerator} (and {@code #@Factor}),
 * {@code #@DropTarget}, with
 * every standard line naming them marked too; the peers' bare {@code Sink}, {@code Accelerator} and {@code Booster}
 * are read as ours, each with a note saying how.
 */
class ExtensionLinesTest {
    private static final String OURS = """
            Circle C 2 2
            LeftFlipper LF 6 16
            #@Sink SK 10 19
            #@Accelerator AC 5 5
            #@Accelerator AD 8 5
            #@Factor AD 2.5
            #@DropTarget DT 12 3
            Connect C LF
            #@Connect SK LF
            #@Connect C AC
            #@KeyConnect key 32 down AD
            #@Connect AC DT
            #@Colour SK 10 20 30
            Gravity 25.0
            Friction 0.025 0.025
            """;

    @Test
    void extensionGizmosAndEveryStandardLineNamingThemAreMarkedAndReadBackEqual() throws BoardFileException {
        Board board = BoardFiles.load("test", OURS);
        assertThat(board.gizmo("SK").orElseThrow().kind()).isEqualTo(GizmoKind.SINK);
        assertThat(board.gizmo("DT").orElseThrow().kind()).isEqualTo(GizmoKind.DROP_TARGET);
        assertThat(((AcceleratorView) board.gizmo("AD").orElseThrow()).factor()).isEqualTo(2.5);
        assertThat(((AcceleratorView) board.gizmo("AC").orElseThrow()).factor()).isEqualTo(1.5);
        String written = BoardFiles.toText(board);
        assertThat(written.lines().filter(l -> !l.startsWith("#@")).toList())
                .as("what a loader of the standard format reads names nothing it lacks")
                .containsExactly("Circle C 2 2", "LeftFlipper LF 6 16", "Connect C LF", "Gravity 25.0",
                        "Friction 0.025 0.025");
        assertThat(BoardContents.of(BoardFiles.load("again", written))).isEqualTo(BoardContents.of(board));
    }

    @Test
    void thePeersSinkAcceleratorAndBoosterAreReadAsOursWithANote() {
        LoadResult result = BoardFiles.loadSkippingBadLines("peer", """
                Sink Sink0 18 10
                Accelerator Accelerator22 3 4
                Booster 12_5 12 5
                Connect Sink0 Accelerator22
                """);
        assertThat(result.skippedLines()).isEmpty();
        Board board = result.board();
        assertThat(board.gizmo("Sink0").orElseThrow().kind()).isEqualTo(GizmoKind.SINK);
        assertThat(board.gizmo("Accelerator22").orElseThrow().kind()).isEqualTo(GizmoKind.ACCELERATOR);
        assertThat(board.gizmo("12_5").orElseThrow().kind()).isEqualTo(GizmoKind.ACCELERATOR);
        assertThat(result.notes()).extracting(BoardFileNote::line, BoardFileNote::note).containsExactly(
                org.assertj.core.groups.Tuple.tuple(1, "'Sink' of another implementation read as #@Sink: a ball that"
                        + " touches it leaves the board, as in the game that wrote it"),
                org.assertj.core.groups.Tuple.tuple(2, "'Accelerator' of another implementation read as #@Accelerator:"
                        + " a round bumper that speeds the ball up 1.5 times a hit (1.4 times in the game that wrote it:"
                        + " #@Factor sets it)"),
                org.assertj.core.groups.Tuple.tuple(3, "'Booster' of another implementation read as #@Accelerator:"
                        + " a round bumper that speeds the ball up 1.5 times a hit (2 times in the game that wrote it:"
                        + " #@Factor sets it)"));
    }
}
