package gizmoball.preview;

import gizmoball.editor.Preview;
import gizmoball.editor.Tool;
import gizmoball.model.Board;
import gizmoball.model.BoardChange;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * Build mode's aim preview: keeps the predicted path of the ball being placed, moved or selected up to date
 * with the editor (every pointer move of a gesture) and with the design (every edit). A prediction is made
 * only when what it depends on changed, in slices of {@link Predictor#BUDGET_NANOS}, so the event thread keeps
 * up with the mouse: the first slice is drawn at once, and {@code later} runs the next ones (on the event
 * thread, after the events already waiting) until the whole horizon is covered or the inputs change.
 */
public final class AimPreview {
    /** What a prediction depends on besides the design: the editor's tool, gesture preview and selection. */
    public record Inputs(Tool tool, Optional<Preview> preview, Optional<String> selected) {
    }

    private final Board design;
    private final Supplier<Inputs> inputs;
    private final Predictor predictor;
    private final Consumer<Runnable> later;
    private final List<Runnable> listeners = new ArrayList<>();
    private boolean enabled;
    private long designVersion;
    private Object madeFor;
    private Optional<Prediction> current = Optional.empty();
    private Predictor.Run running;
    /** The ball last selected: its path stays shown while a gizmo is selected, placed or moved. */
    private String followed;

    public AimPreview(Board design, Supplier<Inputs> inputs, Predictor predictor, Consumer<Runnable> later) {
        this.design = design;
        this.inputs = inputs;
        this.predictor = predictor;
        this.later = later;
        design.addObserver((Board b, BoardChange change) -> {
            if (change != BoardChange.TICK) {
                designVersion++;
                refresh();
            }
        });
    }

    public boolean isEnabled() {
        return enabled;
    }

    /** On only in build mode with View > Aim preview checked; off, it predicts nothing. */
    public void setEnabled(boolean on) {
        enabled = on;
        refresh();
    }

    /** Told after the prediction changed. */
    public void addListener(Runnable listener) {
        listeners.add(listener);
    }

    public Optional<Prediction> current() {
        return current;
    }

    /** Predicts again if the editor or the design changed since the last prediction. */
    public void refresh() {
        Inputs now = enabled ? inputs.get() : null;
        Object key = now == null ? null : List.of(now, designVersion);
        if (Objects.equals(key, madeFor)) {
            return;
        }
        madeFor = key;
        if (now != null) {
            follow(now.selected());
        }
        running = now == null ? null : AimScenario.of(design, now.tool(), now.preview(), now.selected(),
                        Optional.ofNullable(followed))
                .map(s -> predictor.start(s.board(), s.ball(), Predictor.HORIZON_SECONDS, Board.DEFAULT_TICK))
                .orElse(null);
        current = Optional.empty();
        advance(running);
    }

    /** A selected ball is followed; a selected gizmo keeps the ball followed; selecting nothing lets it go. */
    private void follow(Optional<String> selected) {
        if (selected.isEmpty()) {
            followed = null;
        } else if (design.ball(selected.get()).isPresent()) {
            followed = selected.get();
        }
    }

    /** One slice of {@code run}, unless a newer prediction replaced it meanwhile. */
    private void advance(Predictor.Run run) {
        if (run != running) {
            return;
        }
        if (run != null) {
            current = Optional.of(run.advance(Predictor.BUDGET_NANOS));
            if (!run.isDone()) {
                later.accept(() -> advance(run));
            }
        }
        listeners.forEach(Runnable::run);
    }
}
