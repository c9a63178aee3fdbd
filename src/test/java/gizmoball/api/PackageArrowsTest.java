package gizmoball.api;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import gizmoball.headless.HeadlessRunner;
import gizmoball.model.Board;
import gizmoball.view.BoardPainter;

/**
 * The model's arrows run one way (docs/design.md, "Package map"): the board uses the loop, the loop uses the gizmo
 * kinds, and never the other way round: the loop uses nothing of the board it runs on but the kinds, the kinds use
 * nothing of the game outside them, the game rules nothing but the loop and the kinds, and none of them uses AWT or
 * Swing; the lab uses nothing of the game but the model, and no AWT or Swing either. Read from the constant pools of the game's
 * compiled classes, which name every class a class uses (imports that only Javadoc uses leave none).
 */
class PackageArrowsTest {
    private static final String GAME = "gizmoball/";
    private static final String MODEL = "gizmoball/model/";
    private static final String KINDS = "gizmoball/model/gizmo/";
    private static final String LOOP = "gizmoball/model/loop/";
    private static final String GAME_RULES = "gizmoball/model/game/";
    private static final String LAB = "gizmoball/lab/";

    @Test
    void theKindsUseNothingOfTheGameOutsideThemTheLoopOnlyTheKindsAndTheModelAndTheLabNoAwtOrSwing()
            throws IOException, URISyntaxException {
        List<String> kinds = new ArrayList<>();
        List<String> loop = new ArrayList<>();
        List<String> gameRules = new ArrayList<>();
        List<String> lab = new ArrayList<>();
        List<String> violations = new ArrayList<>();
        ApiOnlyTest.forEachGameClassFile((name, refs) -> {
            if (name.startsWith(KINDS)) {
                kinds.add(name);
                violations.addAll(outsideTheKinds(name, refs));
            }
            if (name.startsWith(LOOP)) {
                loop.add(name);
                violations.addAll(outsideTheLoopAndTheKinds(name, refs));
            }
            if (name.startsWith(GAME_RULES)) {
                gameRules.add(name);
                violations.addAll(outsideTheGameRulesTheLoopAndTheKinds(name, refs));
            }
            if (name.startsWith(MODEL)) {
                violations.addAll(awtOrSwing(name, refs));
            }
            if (name.startsWith(LAB)) {
                lab.add(name);
                violations.addAll(outsideTheLabAndTheModel(name, refs));
                violations.addAll(awtOrSwing(name, refs));
            }
        });

        // Not vacuous: the kinds and the loop were found where the package map puts them.
        assertThat(kinds).contains(KINDS + "GizmoBase.class", KINDS + "Flipper.class", KINDS + "Absorber.class");
        assertThat(loop).contains(LOOP + "TickRun.class", LOOP + "CollisionDetector.class", LOOP + "Ball.class");
        assertThat(gameRules).contains(GAME_RULES + "Game.class", GAME_RULES + "GameRules.class");
        assertThat(lab).contains(LAB + "Lab.class", LAB + "AutoPlayer.class");
        assertThat(violations).as("references against the package map's arrows").isEmpty();
    }

    /**
     * Every check can fail: the board's play rules use the rest of the model (the loop's check reports that, and not
     * their uses of the loop and the kinds), the painter uses AWT, the headless runner reads board files.
     */
    @Test
    void theChecksReportAReferenceAgainstTheArrows() throws IOException {
        ClassFileReferences play = read(Board.class, "Play.class");
        assertThat(outsideTheKinds("Play.class", play)).contains("Play.class: " + MODEL + "Registry");
        assertThat(outsideTheLoopAndTheKinds("Play.class", play)).contains("Play.class: " + MODEL + "Registry")
                .doesNotContain("Play.class: " + LOOP + "Ball", "Play.class: " + KINDS + "Absorber");
        assertThat(outsideTheGameRulesTheLoopAndTheKinds("Play.class", play)).contains("Play.class: " + MODEL + "Registry")
                .doesNotContain("Play.class: " + LOOP + "Ball");
        ClassFileReferences painter = read(BoardPainter.class, "BoardPainter.class");
        assertThat(awtOrSwing("BoardPainter.class", painter)).contains("BoardPainter.class: java/awt/Graphics2D");
        ClassFileReferences runner = read(HeadlessRunner.class, "HeadlessRunner.class");
        assertThat(outsideTheLabAndTheModel("HeadlessRunner.class", runner))
                .contains("HeadlessRunner.class: gizmoball/boardfile/BoardFiles")
                .doesNotContain("HeadlessRunner.class: " + LAB + "Lab", "HeadlessRunner.class: " + MODEL + "Board");
    }

    private static List<String> outsideTheKinds(String classFile, ClassFileReferences refs) {
        return refs.classes.stream().filter(c -> c.startsWith(GAME) && !c.startsWith(KINDS)).distinct()
                .map(c -> classFile + ": " + c).toList();
    }

    private static List<String> outsideTheLoopAndTheKinds(String classFile, ClassFileReferences refs) {
        return refs.classes.stream().filter(c -> c.startsWith(GAME) && !c.startsWith(LOOP) && !c.startsWith(KINDS))
                .distinct().map(c -> classFile + ": " + c).toList();
    }

    private static List<String> outsideTheGameRulesTheLoopAndTheKinds(String classFile, ClassFileReferences refs) {
        return refs.classes.stream().filter(c -> c.startsWith(GAME) && !c.startsWith(GAME_RULES) && !c.startsWith(LOOP)
                        && !c.startsWith(KINDS)).distinct().map(c -> classFile + ": " + c).toList();
    }

    /** The lab plays boards through the model's API: it uses nothing else of the game, so any part may use it. */
    private static List<String> outsideTheLabAndTheModel(String classFile, ClassFileReferences refs) {
        return refs.classes.stream().filter(c -> c.startsWith(GAME) && !c.startsWith(LAB) && !c.startsWith(MODEL))
                .distinct().map(c -> classFile + ": " + c).toList();
    }

    private static List<String> awtOrSwing(String classFile, ClassFileReferences refs) {
        return refs.classes.stream().filter(c -> c.startsWith("java/awt/") || c.startsWith("javax/swing/"))
                .distinct().map(c -> classFile + ": " + c).toList();
    }

    private static ClassFileReferences read(Class<?> neighbour, String classFile) throws IOException {
        try (InputStream in = neighbour.getResourceAsStream(classFile)) {
            assertThat(in).as("%s next to %s on the test classpath", classFile, neighbour).isNotNull();
            return ClassFileReferences.read(in);
        }
    }
}
