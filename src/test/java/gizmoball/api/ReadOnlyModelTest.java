package gizmoball.api;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.net.URISyntaxException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;

import gizmoball.model.gizmo.Absorber;
import gizmoball.model.gizmo.AbsorberView;
import gizmoball.model.gizmo.Bumper;
import gizmoball.model.gizmo.BumperView;
import gizmoball.model.gizmo.Flipper;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.loop.Ball;
import gizmoball.model.loop.BallView;

import physics.Vect;

/**
 * Only the model changes balls and gizmos (docs/design.md, "Package map"): views, controllers, the editor and every
 * other package outside {@code gizmoball.model} read them through their read-only types ({@link BallView},
 * {@link Gizmo}, {@link FlipperView}, {@link AbsorberView}, {@link BumperView}), which {@code Board} hands out. The
 * mutable classes keep public mutators only because the board is another package than the kinds and the loop;
 * this test keeps everyone else from them. Read from the constant pools of the game's compiled classes, which name
 * every class a class uses and every member it calls.
 */
class ReadOnlyModelTest {
    private static final String MODEL = "gizmoball/model/";
    /** Each mutable class of the model and the read-only type that others read it as. */
    private static final Map<Class<?>, Class<?>> READ_AS = Map.of(
            Ball.class, BallView.class,
            GizmoBase.class, Gizmo.class,
            Bumper.class, BumperView.class,
            Flipper.class, FlipperView.class,
            Absorber.class, AbsorberView.class);

    @Test
    void noClassOutsideTheModelNamesAMutableBallOrGizmoOrCallsAMutator() throws IOException, URISyntaxException {
        List<String> outside = new ArrayList<>();
        List<String> violations = new ArrayList<>();
        ApiOnlyTest.forEachGameClassFile((name, refs) -> {
            if (!name.startsWith(MODEL)) {
                outside.add(name);
                violations.addAll(violations(name, refs));
            }
        });

        // Not vacuous: the views, the controllers and the editor were read.
        assertThat(outside).contains("gizmoball/view/BoardPainter.class", "gizmoball/editor/Editor.class",
                "gizmoball/controller/GameLoop.class", "gizmoball/view/editor/PropertiesPanel.class");
        assertThat(violations).as("uses of the model's mutable classes outside the model").isEmpty();
    }

    /** The mutators are every public member beyond the read-only type, found by reflection, so new ones count too. */
    @Test
    void theMutatorsAreWhatTheReadOnlyTypesLeaveOut() {
        assertThat(mutators(Ball.class)).contains("moveTo(Lphysics/Vect;)V", "setVelocity(Lphysics/Vect;)V",
                "capture(Lphysics/Vect;)V", "release(Lphysics/Vect;Lphysics/Vect;)V", "copy()Lgizmoball/model/loop/Ball;")
                .doesNotContain("position()Lphysics/Vect;", "isCaptured()Z");
        assertThat(mutators(Flipper.class)).contains("stall()V", "setState(DZ)V", "advance(D)V", "moveTo(II)V",
                "markTriggered(D)V").doesNotContain("angleFromRest()D", "tip()Lphysics/Vect;", "name()Ljava/lang/String;");
        assertThat(mutators(Absorber.class)).contains("hold(Ljava/lang/String;)V", "letGo(Ljava/lang/String;)V")
                .doesNotContain("held()Ljava/util/List;");
    }

    /** The check can fail: a class that moves a ball is reported, its read of a ball's view is not. */
    @Test
    void theCheckReportsAMutatorAndAMutableType() throws IOException {
        try (InputStream in = AViewThatMovesABall.class.getResourceAsStream(
                "ReadOnlyModelTest$AViewThatMovesABall.class")) {
            assertThat(in).isNotNull();
            List<String> found = violations("AViewThatMovesABall.class", ClassFileReferences.read(in));
            assertThat(found).contains(
                    "AViewThatMovesABall.class calls the mutator gizmoball/model/loop/Ball.moveTo(Lphysics/Vect;)V",
                    "AViewThatMovesABall.class names gizmoball/model/loop/Ball: read it as BallView")
                    .noneMatch(v -> v.contains("position") || v.contains("names gizmoball/model/loop/BallView"));
        }
    }

    /** What the check must catch: the shortcut a view could take through the live ball. */
    private static final class AViewThatMovesABall {
        static Vect nudge(BallView seen, Ball ball) {
            ball.moveTo(seen.position());
            return seen.position();
        }
    }

    private static List<String> violations(String classFile, ClassFileReferences refs) {
        List<String> found = new ArrayList<>();
        for (ClassFileReferences.MemberRef member : refs.members) {
            mutableClass(member.owner()).filter(c -> mutators(c).contains(member.name() + member.descriptor()))
                    .ifPresent(c -> found.add(classFile + " calls the mutator " + member));
        }
        refs.classes.stream().distinct().forEach(name -> mutableClass(name).ifPresent(c ->
                found.add(classFile + " names " + name + ": read it as " + READ_AS.get(c).getSimpleName())));
        return found;
    }

    private static Optional<Class<?>> mutableClass(String internalName) {
        return READ_AS.keySet().stream().filter(c -> internalName(c).equals(internalName)).findFirst();
    }

    /** Public methods and constructors of {@code type} that its read-only type does not declare (nor Object). */
    private static Set<String> mutators(Class<?> type) {
        Set<String> readers = Arrays.stream(READ_AS.get(type).getMethods()).map(ReadOnlyModelTest::signature)
                .collect(Collectors.toSet());
        Arrays.stream(Object.class.getMethods()).map(ReadOnlyModelTest::signature).forEach(readers::add);
        Set<String> mutators = new TreeSet<>();
        Arrays.stream(type.getMethods()).map(ReadOnlyModelTest::signature).filter(s -> !readers.contains(s))
                .forEach(mutators::add);
        Arrays.stream(type.getConstructors()).filter(c -> Modifier.isPublic(c.getModifiers()))
                .map(c -> "<init>" + parameters(c.getParameterTypes()) + "V").forEach(mutators::add);
        return mutators;
    }

    private static String signature(Method method) {
        return method.getName() + parameters(method.getParameterTypes()) + method.getReturnType().descriptorString();
    }

    private static String parameters(Class<?>[] types) {
        return Arrays.stream(types).map(Class::descriptorString).collect(Collectors.joining("", "(", ")"));
    }

    private static String internalName(Class<?> type) {
        return type.getName().replace('.', '/');
    }
}
