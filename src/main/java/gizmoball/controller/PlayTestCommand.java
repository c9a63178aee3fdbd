package gizmoball.controller;

import gizmoball.model.Board;
import java.awt.Window;
import java.util.function.Supplier;

/**
 * Build mode's Test > Play-test: starts a {@link PlayTest} of the design, or, while one is still playing, brings its
 * window to the front instead of starting a second lab beside it (two would share the cores, each taking twice as
 * long, and their windows would be told apart only by where they stand).
 */
public final class PlayTestCommand {
    private final Window owner;
    private final Supplier<Board> design;
    private final Supplier<String> boardName;
    /** The play-test started last; null before the first. */
    private PlayTest last;

    public PlayTestCommand(Window owner, Supplier<Board> design, Supplier<String> boardName) {
        this.owner = owner;
        this.design = design;
        this.boardName = boardName;
    }

    /** Call on the event thread. */
    public void run() {
        if (last != null && !last.isDone()) {
            last.dialog().toFront();
            return;
        }
        last = PlayTest.start(owner, design.get(), boardName.get(), PlayTest.settings());
    }
}
