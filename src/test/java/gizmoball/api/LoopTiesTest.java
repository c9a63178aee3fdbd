package gizmoball.api;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.URISyntaxException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

import org.junit.jupiter.api.Test;

/**
 * No two files of the loop use each other (docs/design.md, "Package map"): within the package, too, the arrows run
 * one way, so that each file can be read knowing only the ones it uses. A nested class counts as its file. Read from
 * the compiled classes' constant pools, like {@link PackageArrowsTest}.
 */
class LoopTiesTest {
    private static final String LOOP = "gizmoball/model/loop/";
    /**
     * The ties the loop keeps, each for its reason; the list may only shrink. A sealed type names the types it
     * permits, and they name it, so such a pair is one type's two halves.
     */
    private static final Map<String, String> KEPT = Map.of(
            "Ball <-> BallView", "the read-only view is sealed and permits only the ball",
            "Struck <-> TriggerSource", "what a ball strikes is sealed and permits the trigger sources",
            "Ball <-> Contact", "a ball keeps its own contact value, so that asking about a pair of balls makes no "
                    + "object in the tick (docs/design.md, \"The tick\")");

    @Test
    void noTwoFilesOfTheLoopUseEachOther() throws IOException, URISyntaxException {
        Map<String, Set<String>> uses = new TreeMap<>();
        ApiOnlyTest.forEachGameClassFile((name, refs) -> {
            if (name.startsWith(LOOP)) {
                Set<String> used = uses.computeIfAbsent(file(name), f -> new TreeSet<>());
                refs.classes.stream().filter(c -> c.startsWith(LOOP)).map(LoopTiesTest::file).forEach(used::add);
            }
        });

        assertThat(uses).as("the loop's files were found").containsKeys("CollisionDetector", "Contact", "Ball");
        List<String> ties = twoWayTies(uses);
        assertThat(ties).as("ties outside the kept list").isSubsetOf(KEPT.keySet());
        assertThat(KEPT.keySet()).as("kept ties that are gone (take them off the list)").isSubsetOf(ties);
    }

    /** The check can fail: a pair that names each other is a tie, a pair where one names the other is not. */
    @Test
    void aPairThatUsesEachOtherIsATie() {
        Map<String, Set<String>> uses = Map.of("A", Set.of("B"), "B", Set.of("A", "C"), "C", Set.of());
        assertThat(twoWayTies(uses)).containsExactly("A <-> B");
    }

    private static List<String> twoWayTies(Map<String, Set<String>> uses) {
        List<String> ties = new ArrayList<>();
        new TreeMap<>(uses).forEach((file, used) -> used.stream()
                .filter(other -> file.compareTo(other) < 0 && uses.getOrDefault(other, Set.of()).contains(file))
                .forEach(other -> ties.add(file + " <-> " + other)));
        return ties;
    }

    /** The file a class of the loop lives in: its name up to the first {@code $}, without the package. */
    private static String file(String classFileOrName) {
        String name = classFileOrName.substring(LOOP.length()).replace(".class", "");
        int nested = name.indexOf('$');
        return nested < 0 ? name : name.substring(0, nested);
    }
}
