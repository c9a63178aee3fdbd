package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.gizmo.AcceleratorView;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.PortalView;
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
            #@Portal P1 14 14
            #@Portal P2 3 14
            #@Portal P3 8 10
            #@Rotate P2
            #@Pair P2 P1
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
        assertThat(((PortalView) board.gizmo("P1").orElseThrow()).pair()).contains("P2");
        assertThat(((PortalView) board.gizmo("P3").orElseThrow()).pair()).isEmpty();
        assertThat(BoardFiles.toText(board)).as("written once, from the first in the board's order")
                .contains("#@Pair P1 P2\n").doesNotContain("#@Pair P2 P1");
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
    void thePeersPortalsTeleportersAndTheirLinksAreReadAsOursAndALinkToASecondPortalIsRefused() {
        LoadResult result = BoardFiles.loadSkippingBadLines("peer", """
                Portal Portal12 11 12
                Portal Portal13 13 4
                Portal Portal14 5 4
                Teleporter TEL23 2 3
                Teleporter TEL123 12 3
                Rotate TEL23
                TeleporterConnect TEL23 TEL123
                Connect Portal12 Portal14
                Connect Portal14 Portal13
                Connect Portal12 Portal14
                #@Connect Portal13 Portal12
                Portal P1 1 9 17 1
                """);
        Board board = result.board();
        assertThat(((PortalView) board.gizmo("Portal12").orElseThrow()).pair()).contains("Portal14");
        assertThat(((PortalView) board.gizmo("TEL123").orElseThrow()).pair()).contains("TEL23");
        assertThat(((PortalView) board.gizmo("Portal13").orElseThrow()).pair()).as("ours is a connection").isEmpty();
        assertThat(board.gizmo("TEL23").orElseThrow().rotation()).isEqualTo(1);
        assertThat(board.connections()).hasSize(1);
        assertThat(result.skippedLines()).extracting(BoardFileError::line, BoardFileError::reason).containsExactly(
                org.assertj.core.groups.Tuple.tuple(9, "portal Portal14 is paired with Portal12 already: a portal of"
                        + " this game has one pair, a ball going through it both ways"),
                org.assertj.core.groups.Tuple.tuple(10, "Portal12 and Portal14 are paired already"),
                org.assertj.core.groups.Tuple.tuple(12, "wrong number of arguments: 'Portal' of another implementation"
                        + " is read as #@Portal, which takes 3 (#@Portal <name> <x> <y>), found 5: a portal and the cell"
                        + " of its exit on one line, another implementation's form whose exit has no name; this game's"
                        + " portals are two gizmos, each #@Portal <name> <x> <y>, joined by #@Pair"));
        assertThat(result.notes()).extracting(BoardFileNote::line).containsExactly(1, 2, 3, 4, 5, 7, 8);
        assertThat(result.notes().get(6).note()).isEqualTo("'Connect' from a portal to a portal, another"
                + " implementation's link, read as #@Pair Portal12 Portal14: a ball entering either leaves by the other"
                + " (in the game that wrote it, from Portal12 to Portal14)");
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
