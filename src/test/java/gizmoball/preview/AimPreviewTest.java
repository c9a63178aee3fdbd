package gizmoball.preview;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.editor.Preview;
import gizmoball.editor.Tool;
import gizmoball.model.Board;
import gizmoball.model.gizmo.GizmoKind;
import java.util.ArrayDeque;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** The preview follows the editor and the design, predicting only when something it depends on changed. */
class AimPreviewTest {
    private final Board design = new Board();
    private final ArrayDeque<Runnable> later = new ArrayDeque<>();
    private AimPreview.Inputs inputs = new AimPreview.Inputs(Tool.SELECT, Optional.empty(), Optional.of("B"));
    private int predictions;
    private final Predictor predictor = new Predictor(() -> 0L);
    private final AimPreview aim = new AimPreview(design, () -> inputs, predictor, later::add);

    AimPreviewTest() {
        design.addBall("B", 10.5, 2, 0, 0);
        aim.addListener(() -> predictions++);
    }

    @Test
    void offItPredictsNothing() {
        aim.refresh();
        assertThat(aim.current()).isEmpty();
        assertThat(predictions).isZero();
    }

    @Test
    void itPredictsAgainOnlyWhenTheEditorOrTheDesignChanged() {
        aim.setEnabled(true);
        assertThat(aim.current()).isPresent();
        assertThat(aim.current().get().ticks()).isEqualTo(180);
        int made = predictions;
        aim.refresh();
        aim.refresh();
        assertThat(predictions).as("same inputs, same design").isEqualTo(made);

        inputs = new AimPreview.Inputs(Tool.SQUARE, Optional.of(new Preview.Footprint(10, 10, 1, 1, Optional.empty())),
                Optional.of("B"));
        aim.refresh();
        assertThat(predictions).isEqualTo(made + 1);
        assertThat(aim.current().get().path().stream().mapToDouble(p -> p.at().y()).max().orElseThrow())
                .as("stopped by the square being placed").isLessThanOrEqualTo(9.75 + 1e-9);

        inputs = new AimPreview.Inputs(Tool.SELECT, Optional.empty(), Optional.of("B"));
        design.addGizmo(GizmoKind.SQUARE, "S", 10, 14);   // an edit: predicted again without an editor event
        assertThat(predictions).isEqualTo(made + 2);
        assertThat(aim.current().get().path().stream().mapToDouble(p -> p.at().y()).max().orElseThrow())
                .isLessThanOrEqualTo(13.75 + 1e-9);
        assertThat(later).as("no slice left over with an unlimited budget").isEmpty();
    }

    @Test
    void aSlowPredictionCarriesOnInLaterSlices() {
        long[] now = {0};
        AimPreview slow = new AimPreview(design, () -> inputs, new Predictor(() -> now[0] += 1_000_000), later::add);
        slow.setEnabled(true);
        assertThat(slow.current().orElseThrow().shortened()).isTrue();
        int slices = 1;
        while (!later.isEmpty()) {
            later.poll().run();
            slices++;
        }
        assertThat(slices).isGreaterThan(1);
        assertThat(slow.current().orElseThrow().shortened()).isFalse();
        assertThat(slow.current().get().ticks()).isEqualTo(180);
    }

    @Test
    void theSelectedBallsPathStaysWhileAGizmoIsSelectedAndMoved() {
        design.addGizmo(GizmoKind.SQUARE, "S", 3, 3);
        aim.setEnabled(true);
        Prediction ofBall = aim.current().orElseThrow();
        inputs = new AimPreview.Inputs(Tool.SELECT, Optional.empty(), Optional.of("S"));
        aim.refresh();
        assertThat(aim.current().orElseThrow().ball()).as("still following B").isEqualTo("B");
        assertThat(aim.current().get().path()).isEqualTo(ofBall.path());

        // Dragging S under the falling ball: the footprint at (10, 12) bends B's path before the drop.
        inputs = new AimPreview.Inputs(Tool.SELECT, Optional.of(new Preview.Footprint(10, 12, 1, 1, Optional.empty())),
                Optional.of("S"));
        aim.refresh();
        assertThat(aim.current().orElseThrow().path().stream().mapToDouble(p -> p.at().y()).max().orElseThrow())
                .isLessThanOrEqualTo(11.75 + 1e-9);

        inputs = new AimPreview.Inputs(Tool.SELECT, Optional.empty(), Optional.empty());
        aim.refresh();
        assertThat(aim.current()).as("nothing selected: nothing followed").isEmpty();
    }
}
