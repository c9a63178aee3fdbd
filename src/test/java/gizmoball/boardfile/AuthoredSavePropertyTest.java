package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Issue 23, item 1: random edits to random commented files. The saved file holds every comment and blank line in
 * their order, and loads to exactly the edited board; so does a second save after more edits.
 */
class AuthoredSavePropertyTest {
    private static final long SEED = 23_2026L;
    private static final int FILES = 300;
    private static final GizmoKind[] KINDS = {GizmoKind.SQUARE, GizmoKind.CIRCLE, GizmoKind.TRIANGLE,
            GizmoKind.LEFT_FLIPPER, GizmoKind.RIGHT_FLIPPER};

    private final Random random = new Random(SEED);

    @Test
    void randomEditsToCommentedFilesKeepEveryCommentAndLoadToTheEditedBoard() {
        RandomBoards boards = new RandomBoards(random);
        for (int i = 0; i < FILES; i++) {
            String text = commented(BoardFiles.toText(boards.next()));
            LoadResult loaded = BoardFiles.loadSkippingBadLines("f", text);
            String description = "seed " + SEED + " file " + i + ":\n" + text;
            assertThat(loaded.skippedLines()).as(description).isEmpty();
            Board board = loaded.board();

            edit(board);
            SavePlan first = loaded.authored().saving(board);
            assertKeepsCommentsAndLoadsTo(text, first, board, description);

            edit(board);
            SavePlan second = first.saved().saving(board);
            assertKeepsCommentsAndLoadsTo(text, second, board, description + "\nsaved once:\n" + first.text());
        }
    }

    private static void assertKeepsCommentsAndLoadsTo(String original, SavePlan plan, Board edited, String description) {
        assertThat(plan.lost().total()).as("lines lost, %s", description).isZero();
        assertThat(notCommands(plan.text())).as(description).isEqualTo(notCommands(original));
        LoadResult reloaded = BoardFiles.loadSkippingBadLines("saved", plan.text());
        assertThat(reloaded.skippedLines()).as("%s%nsaved:%n%s", description, plan.text()).isEmpty();
        assertThat(BoardContents.of(edited).withSetsSorted()
                .differences(BoardContents.of(reloaded.board()).withSetsSorted()))
                .as("%s%nsaved:%n%s", description, plan.text()).isEmpty();
    }

    /** The comments and blank lines, in order. */
    private static List<String> notCommands(String text) {
        return text.lines().filter(l -> l.isBlank() || l.startsWith("# ")).toList();
    }

    /** The canonical text with comments and blank lines between its lines, and some lines spaced by hand. */
    private String commented(String canonical) {
        StringBuilder out = new StringBuilder("# a board by hand\n");
        for (String line : canonical.lines().toList()) {
            if (random.nextInt(4) == 0) {
                out.append(random.nextBoolean() ? "\n" : "# about what follows " + random.nextInt(100) + "\n");
            }
            out.append(random.nextInt(5) == 0 ? line.replace(" ", "   ") : line).append('\n');
        }
        return out.append(random.nextBoolean() ? "# the end\n" : "").toString();
    }

    /** A few edits of any kind, each through the board's own operations (refused ones change nothing). */
    private void edit(Board board) {
        int edits = 1 + random.nextInt(6);
        for (int i = 0; i < edits; i++) {
            attempt(() -> oneEdit(board));
        }
    }

    private void oneEdit(Board board) {
        List<String> gizmos = board.gizmos().stream().map(Gizmo::name).toList();
        List<String> balls = board.balls().stream().map(BallView::name).toList();
        switch (random.nextInt(18)) {
            case 0 -> board.addGizmo(KINDS[random.nextInt(KINDS.length)], "N" + random.nextInt(1000),
                    random.nextInt(20), random.nextInt(20));
            case 1 -> board.moveGizmo(pick(gizmos), random.nextInt(20), random.nextInt(20));
            case 2 -> board.delete(pick(gizmos));
            case 3 -> board.rotate(pick(gizmos));
            case 4 -> board.setColour(pick(gizmos), random.nextBoolean() ? Optional.empty()
                    : Optional.of(Rgb.of(random.nextInt(1 << 24))));
            case 5 -> board.addBall("NB" + random.nextInt(1000), 0.5 + random.nextInt(19), 0.5 + random.nextInt(19),
                    random.nextInt(5), 0);
            case 6 -> board.moveBall(pick(balls), 0.5 + random.nextInt(19), 0.5 + random.nextInt(19));
            case 7 -> board.delete(pick(balls));
            case 8 -> board.connect(random.nextInt(4) == 0 ? TriggerSource.OUTER_WALLS
                    : TriggerSource.gizmo(pick(gizmos)), pick(gizmos));
            case 9 -> {
                Connection c = pick(board.connections());
                board.disconnect(c.source(), c.target());
            }
            case 10 -> board.bindKey(65 + random.nextInt(26), KeyEdge.values()[random.nextInt(3)], pick(gizmos));
            case 11 -> {
                KeyBinding k = pick(board.keyBindings());
                board.unbindKey(k.keyCode(), k.edge(), k.gizmo());
            }
            case 12 -> board.setGravity(random.nextInt(50));
            case 13 -> board.setBallsPerGame(1 + random.nextInt(5));
            case 14 -> board.setExtraBallAt(random.nextBoolean() ? OptionalLong.empty()
                    : OptionalLong.of(1000L * random.nextInt(10)));
            case 15 -> board.setDrain(pick(gizmos), random.nextBoolean());
            case 16 -> board.setPoints(pick(gizmos), random.nextInt(200));
            default -> board.setFriction(random.nextInt(10) / 100.0, random.nextInt(10) / 100.0);
        }
    }

    private <T> T pick(List<T> from) {
        if (from.isEmpty()) {
            throw new BoardEditException("nothing to pick");
        }
        return new ArrayList<>(from).get(random.nextInt(from.size()));
    }

    private static void attempt(Runnable edit) {
        try {
            edit.run();
        } catch (BoardEditException refused) {
            // refused: the board is as it was, and another edit follows
        }
    }
}
