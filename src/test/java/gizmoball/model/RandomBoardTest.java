package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.LoopMode;
import gizmoball.model.loop.TriggerSource;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Random valid boards (fixed seeds), played with random triggers: the invariants hold after every tick. */
class RandomBoardTest {
    private static final GizmoKind[] KINDS = {GizmoKind.SQUARE, GizmoKind.CIRCLE, GizmoKind.TRIANGLE,
            GizmoKind.LEFT_FLIPPER, GizmoKind.RIGHT_FLIPPER};

    /** A board of up to 40 gizmos, an absorber, up to 8 balls and some connections; refused placements skipped. */
    static Board randomBoard(Random random) {
        Board board = new Board();
        board.setLoopMode(random.nextInt(4) == 0 ? LoopMode.SEED : LoopMode.CONTINUOUS);
        int y = 16 + random.nextInt(3);
        board.addAbsorber("A", random.nextInt(5), y, 15 + random.nextInt(6), y + 1 + random.nextInt(2));
        for (int i = 0; i < 40; i++) {
            try {
                board.addGizmo(KINDS[random.nextInt(KINDS.length)], "G" + i, random.nextInt(20), random.nextInt(16));
                for (int k = random.nextInt(4); k > 0; k--) {
                    board.rotate("G" + i);
                }
            } catch (BoardEditException refused) {
                // overlapping or off the board: the random board simply has one gizmo fewer
            }
        }
        for (int i = 0; i < 8; i++) {
            try {
                board.addBall("B" + i, 0.25 + 19.5 * random.nextDouble(), 0.25 + 15 * random.nextDouble(),
                        30 * random.nextGaussian(), 30 * random.nextGaussian());
            } catch (BoardEditException refused) {
                // on a gizmo or another ball: one ball fewer
            }
        }
        List<Gizmo> gizmos = board.gizmos();
        for (int i = 0; i < 10; i++) {
            TriggerSource source = random.nextInt(5) == 0 ? TriggerSource.OUTER_WALLS
                    : TriggerSource.gizmo(gizmos.get(random.nextInt(gizmos.size())).name());
            try {
                board.connect(source, gizmos.get(random.nextInt(gizmos.size())).name());
            } catch (BoardEditException duplicate) {
                // already connected
            }
        }
        board.setFriction(random.nextDouble() * 0.05, random.nextDouble() * 0.05);
        board.setGravity(random.nextDouble() * 40);
        return board;
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void invariantsHoldAfterEveryTick(long seed) {
        Random random = new Random(seed);
        Board board = randomBoard(random);
        List<Gizmo> gizmos = board.gizmos();
        for (int tick = 0; tick < 2_000; tick++) {
            if (random.nextInt(20) == 0) {
                board.trigger(gizmos.get(random.nextInt(gizmos.size())).name());
            }
            board.tick(Board.DEFAULT_TICK);
            assertThat(Invariants.violations(board)).as("seed %d tick %d", seed, tick).isEmpty();
        }
    }

    @org.junit.jupiter.api.Test
    void aLongRunOfAHundredThousandTicksKeepsTheInvariants() {
        long seed = 100_000;
        Random random = new Random(seed);
        Board board = randomBoard(random);
        board.setLoopMode(LoopMode.CONTINUOUS);
        List<Gizmo> gizmos = board.gizmos();
        for (int tick = 0; tick < 100_000; tick++) {
            if (random.nextInt(20) == 0) {
                board.trigger(gizmos.get(random.nextInt(gizmos.size())).name());
            }
            board.tick(Board.DEFAULT_TICK);
            assertThat(Invariants.violations(board)).as("seed %d tick %d", seed, tick).isEmpty();
        }
    }

    /** The grid only saves work: with or without it every tick gives bit-for-bit the same board. */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {11, 12, 13})
    void theSpatialIndexChangesNothingButTheWork(long seed) {
        Board indexed = randomBoard(new Random(seed));
        Board scanned = indexed.copy();
        scanned.setSpatialIndexEnabled(false);
        for (int tick = 0; tick < 1_000; tick++) {
            if (tick % 50 == 0) {
                String name = indexed.gizmos().get(tick / 50 % indexed.gizmos().size()).name();
                indexed.trigger(name);
                scanned.trigger(name);
            }
            indexed.tick(Board.DEFAULT_TICK);
            scanned.tick(Board.DEFAULT_TICK);
            assertThat(BoardSnapshot.of(scanned)).as("seed %d tick %d", seed, tick).isEqualTo(BoardSnapshot.of(indexed));
        }
    }
}
