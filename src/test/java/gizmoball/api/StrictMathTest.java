package gizmoball.api;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;

import gizmoball.Main;
import physics.Vect;

/**
 * Play is deterministic on any machine (docs/design.md, "Arithmetic that differs between machines"): what feeds the
 * simulation uses {@code StrictMath} for the functions whose {@code Math} forms may differ between JVMs and
 * processors (HotSpot's intrinsics for {@code sin} and {@code cos} are not fdlibm's). Reads the constant pool of every
 * class of physics-lib and of the game's packages that play (the model, the lab's players, replays, the headless
 * runner): none may call those {@code java.lang.Math} methods. ({@code sqrt} and the arithmetic are exact in both;
 * {@code Math.hypot} is {@code StrictMath.hypot} in Java 17, but a caller cannot know that, so it is refused too.)
 */
class StrictMathTest {
    private static final Set<String> MACHINE_DEPENDENT = Set.of("sin", "cos", "tan", "asin", "acos", "atan", "atan2",
            "exp", "expm1", "log", "log10", "log1p", "pow", "cbrt", "sinh", "cosh", "tanh");
    private static final List<String> PLAYING = List.of("gizmoball/model/", "gizmoball/lab/", "gizmoball/replay/",
            "gizmoball/headless/");

    @Test
    void physicsLibCallsNoMachineDependentMath() throws IOException, URISyntaxException {
        List<String> calls = new ArrayList<>();
        ApiOnlyTest.forEachClassFile(Path.of(Vect.class.getProtectionDomain().getCodeSource().getLocation().toURI()),
                (name, refs) -> calls.addAll(machineDependentCalls(name, refs)));
        assertThat(calls).isEmpty();
    }

    @Test
    void theGamesPlayingPackagesCallNoMachineDependentMath() throws IOException, URISyntaxException {
        List<String> calls = new ArrayList<>();
        List<String> read = new ArrayList<>();
        ApiOnlyTest.forEachClassFile(Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI()),
                (name, refs) -> {
                    if (PLAYING.stream().anyMatch(name::startsWith)) {
                        read.add(name);
                        calls.addAll(machineDependentCalls(name, refs));
                    }
                });
        assertThat(read).as("classes read").hasSizeGreaterThan(100);
        assertThat(calls).isEmpty();
    }

    private static List<String> machineDependentCalls(String className, ClassFileReferences refs) {
        return refs.members.stream()
                .filter(m -> m.owner().equals("java/lang/Math") && (MACHINE_DEPENDENT.contains(m.name())
                        || m.name().equals("hypot")))
                .map(m -> className + " calls " + m)
                .toList();
    }
}
