package gizmoball.fuzz;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The four reproductions of issue 20 (copies of {@code ../shared/repro/} in the test resources), each played for the
 * ticks its first line names with its key script and checked after every tick by the fuzz's own checker: no ball
 * inside a flipper, a gizmo or a ball by more than 1e-6 L, no guard, no tick at the collision cap, no ball in free
 * flight stopped, nothing else the checker forbids. {@code frozen.txt} runs its 4,182 ticks: from tick 3,469 every
 * tick hit the collision cap and 23 balls stopped in mid-air.
 */
class Issue20ReproductionsTest {

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"pivot-end.txt", "stops-inside.txt", "tongs.txt", "frozen.txt"})
    void playsCleanly(String file) throws Exception {
        assertPlaysCleanly("/repro/", file);
    }

    /**
     * Boards of our own fuzz ({@code gradle fuzz}) that once ran into the collision cap. Seed 1000190: a ball that met
     * another and then, at the same instant, a sink's corner was solved as a cluster, whose rows skip what a sink
     * takes, so nothing changed and it met the corner again 400 times. Seeds 1000149, 1000115 and 1000989: balls
     * sliding past each other where they just fit (two in a slot 1 L wide, four in a 1x1 box), closing only as a
     * graze, made cluster rows no impulse within the speed limit could satisfy, or the detector met again what the
     * cluster let pass. Seed 1000101 (with gates and drop targets drawn): without gravity, a ball between a
     * flipper's face and a circle 0.6 degrees from flat bounced between them 4,900 times at no time apart. Seeds
     * 1000864 and 1000286 (spinners and portals drawn too): a row of balls on the floor that just fits between the
     * left wall and a square (a triangle), pushed along: the solve set the row moving, and each ball's rest on its
     * neighbour then took away what pressed into the neighbour as if it stood still, which sent the end ball back
     * into the square, 400 times a tick. Seed 13000553 (a packed pocket drawn): a row that only nearly depended on
     * the active set's was taken as proof that the cluster had no answer, and the pocket met itself again at no time
     * apart to the cap. Seeds 1000117, 1000384 and 1000596 (200 balls, spawners fed by the walls), each from the
     * tick before its guard: a pile of more balls than a cluster holds, the ones beyond falling onto the rest, pushed
     * the cluster into the floor as surfaces moving at their speed; no velocity satisfied that, and the cluster met
     * itself again at no time apart to the cap. Seed 1000117 again, at tick 1,407 (200 balls): a pocket packed with 32
     * balls whose 47 rows so nearly depend on each other that neither the exact solve nor 500 sweeps of Gauss-Seidel
     * left them closing on nothing; it met itself 400 times in one tick, to the cap, in 0.3 s.
     */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"sink-corner-in-a-chain.txt", "passing-in-a-slot.txt", "sliding-past-in-a-slot.txt",
            "four-in-a-box.txt", "nearly-flat-wedge.txt", "row-pushed-along.txt", "resting-on-a-moving-ball.txt",
            "pocket-nearly-dependent.txt", "pocket-beyond-the-limit-1000117.txt",
            "pocket-beyond-the-limit-1000384.txt", "pocket-beyond-the-limit-1000596.txt",
            "pocket-nearly-dependent-1000117.txt"})
    void boardsTheFuzzFoundPlayCleanly(String file) throws Exception {
        assertPlaysCleanly("/fuzz-found/", file);
    }

    private static void assertPlaysCleanly(String folder, String file) throws Exception {
        Reproduction reproduction = Reproduction.parse(file, resource(folder + file));
        Board board = reproduction.load(file);

        FuzzPlay.Outcome outcome = FuzzPlay.play(board, reproduction.keys(), reproduction.ticks(), FuzzPlay.UNTIMED);

        assertThat(outcome.clean()).as("%s: %s", file, outcome.summary()).isTrue();
        assertThat(outcome.capTicks()).as("ticks at the collision cap").isZero();
        assertThat(outcome.ticksPlayed()).as("ticks played").isEqualTo(reproduction.ticks());
    }

    private static String resource(String path) throws IOException {
        try (InputStream in = Issue20ReproductionsTest.class.getResourceAsStream(path)) {
            assertThat(in).as("test resource %s", path).isNotNull();
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }
}
