package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.clickMenu;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.app.Gizmoball;
import gizmoball.app.PlayFeatures;
import gizmoball.controller.Settings;
import gizmoball.controller.Speed;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.preview.AimPreview;
import gizmoball.preview.Prediction;
import java.awt.Rectangle;
import java.awt.event.WindowEvent;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** Game > Speed, View > Ball trails and the settings that a second window (the next run) finds again. */
class PlayFeaturesGuiTest extends GameWindowFixture {
    private PlayFeatures features;


    private GameWindow open() {
        app = Gizmoball.launch(null, settings);
        features = app.playFeatures();
        return app.window();
    }

    /** As the player closes it: the window hears windowClosing, then goes. */
    private static void closeAsPlayer(GameWindow window) {
        onEdt(() -> {
            window.dispatchEvent(new WindowEvent(window, WindowEvent.WINDOW_CLOSING));
            window.dispose();
        });
    }

    @Test
    void theSpeedMenuSetsTheLoopsSpeedShowsItAndIsRemembered() {
        GameWindow window = open();
        assertThat(onEdt(() -> window.statusLine().text())).contains("at 1x");
        clickMenu(window.menus(), "1/4x");
        assertThat(onEdt(() -> app.loop().speed())).isEqualTo(Speed.QUARTER);
        await("the status line to show the speed", () -> window.statusLine().text().contains("Play - stopped at 1/4x"));
        closeAsPlayer(window);

        GameWindow next = open();
        assertThat(onEdt(() -> app.loop().speed())).isEqualTo(Speed.QUARTER);
        assertThat(onEdt(() -> Gui.menuItem(next.menus(), "1/4x").isSelected())).isTrue();
        assertThat(onEdt(() -> next.statusLine().text())).contains("at 1/4x");
    }

    /** Issue 40 item 2: the trails go when the game stops (a stopped board shows no motion). */
    @Test
    void theTrailsGoWhenTheGameStops() {
        GameWindow window = open();
        onEdt(() -> app.session().board().addBall("B", 10.5, 5.5, 3, 0));
        clickMenu(window.menus(), "Ball trails");
        clickMenu(window.menus(), "Start");
        await("a trail", () -> features.trails().trail("B").size() > 2);
        clickMenu(window.menus(), "Stop");
        assertThat(onEdt(() -> features.trails().trail("B"))).isEmpty();
    }

    /** Issue 40 item 13: How to play says where the settings and high scores are kept and how to move them. */
    @Test
    void howToPlaySaysWhereTheSettingsAreKept() {
        GameWindow window = open();
        javax.swing.SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), HelpPages.HOW_TO_PLAY + "...")
                .doClick(0));
        await("the page", () -> Gui.showingWindow("help").isPresent());
        java.awt.Window help = Gui.showingWindow("help").orElseThrow();
        String page = onEdt(() -> Gui.find(help, javax.swing.JEditorPane.class, p -> true).orElseThrow().getText());
        onEdt(help::dispose);
        java.nio.file.Path folder = java.nio.file.Path.of(System.getProperty(Settings.PREFS_ROOT), ".java",
                ".userPrefs", node.absolutePath().substring(1));
        assertThat(page).contains(folder.toString(), "-Djava.util.prefs.userRoot=FOLDER");
    }

    @Test
    void trailsAndWindowPlaceAreRemembered() {
        GameWindow window = open();
        clickMenu(window.menus(), "Ball trails");
        assertThat(onEdt(() -> features.trails().isEnabled())).isTrue();
        Rectangle placed = new Rectangle(40, 60, 700, 720);
        onEdt(() -> window.setBounds(placed));
        await("the window to move", () -> window.getBounds().equals(placed));
        closeAsPlayer(window);

        GameWindow next = open();
        assertThat(onEdt(() -> Gui.menuItem(next.menus(), "Ball trails").isSelected())).isTrue();
        await("the window where it was", () -> next.getBounds().equals(placed));
    }

    @Test
    void inBuildModeTheSelectedBallsPathIsPredictedAndFollowsEdits() {
        app = Gizmoball.launch(Path.of("boards", "multiball.txt"), settings);
        AimPreview aim = app.playFeatures().aimPreview();
        assertThat(onEdt(aim::current)).as("play mode shows no preview").isEmpty();
        clickMenu(app.window().menus(), "Build");
        onEdt(() -> app.build().controller().select("B3"));
        onEdt(aim::refresh);
        Prediction first = onEdt(() -> aim.current().orElseThrow());
        assertThat(first.ball()).isEqualTo("B3");
        assertThat(first.ticks()).isPositive();

        // The ball falls from (11, 1.5), moving right at 3 L/s: a square just under it (cell 11, 2) changes the path at once.
        onEdt(() -> app.session().board().addGizmo(GizmoKind.SQUARE, "InTheWay", 11, 2));
        Prediction after = onEdt(() -> aim.current().orElseThrow());
        assertThat(after.path()).isNotEqualTo(first.path());

        clickMenu(app.window().menus(), "Aim preview");
        assertThat(onEdt(aim::current)).as("View > Aim preview off").isEmpty();
        assertThat(settings.aimPreview()).isFalse();
    }
}
