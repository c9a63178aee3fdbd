package gizmoball.session;

import gizmoball.model.Board;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.BiPredicate;
import java.util.function.Consumer;

/**
 * The state of one window: the one Board that every view observes for the window's whole life, the
 * mode, the design (the board as built, which play mode starts from and Reset returns to), the file it
 * came from and whether it has unsaved changes. Loading, resetting and switching modes replace the
 * board's contents rather than the Board object, so observers never need re-wiring.
 */
public final class GameSession {
    private final Board board = new Board();
    private Board design = board.copy();
    /** The design as last loaded or saved, to tell an edit that brings it back (an undo) from one that changes it. */
    private Board saved = design.copy();
    private Mode mode = Mode.PLAY;
    private boolean modified;
    private Path file;
    /** The sample board shown, for a board that has no file but came with the game; else null. */
    private String sample;
    /** Lines of {@link #file} that the design lacks because they were skipped when it was loaded. */
    private int linesLeftOut;
    private final List<Consumer<Mode>> modeListeners = new ArrayList<>();
    private final List<Runnable> stateListeners = new ArrayList<>();

    public Board board() {
        return board;
    }

    public Mode mode() {
        return mode;
    }

    /** BUILD to PLAY remembers the board as the design; PLAY to BUILD puts the design back (balls where they started). */
    public void setMode(Mode m) {
        if (m == mode) {
            return;
        }
        if (m == Mode.PLAY) {
            design = board.copy();
        } else {
            board.replaceContents(design);
        }
        mode = m;
        modeListeners.forEach(l -> l.accept(m));
        fireStateChanged();
    }

    public void addModeListener(Consumer<Mode> l) {
        modeListeners.add(l);
    }

    /** Called on any change of the file, the modified flag or the mode (the window's title and status follow it). */
    public void addStateListener(Runnable l) {
        stateListeners.add(l);
    }

    public boolean isModified() {
        return modified;
    }

    public void markModified() {
        setModified(true);
    }

    /**
     * The design was edited: it is unsaved unless {@code sameDesign} finds it as it was last loaded or saved (an
     * undo back to there; a board loaded without some of its file's lines stays unsaved).
     */
    public void designEdited(BiPredicate<Board, Board> sameDesign) {
        setModified(linesLeftOut > 0 || !sameDesign.test(boardToSave(), saved));
    }

    private void setModified(boolean now) {
        if (modified != now) {
            modified = now;
            fireStateChanged();
        }
    }

    public Optional<Path> file() {
        return Optional.ofNullable(file);
    }

    /** The name players see: the file name, the sample's ("default.txt (sample)"), or "untitled". */
    public String boardName() {
        if (file != null) {
            return String.valueOf(file.getFileName());
        }
        return sample == null ? "untitled" : sample + " (sample)";
    }

    /** The name Save As offers for a board without a file: the sample's, or untitled.txt. */
    public String suggestedFileName() {
        return sample == null ? "untitled.txt" : sample;
    }

    /** What Save writes: the design. In play mode that is the board as built, not the balls in flight. */
    public Board boardToSave() {
        return mode == Mode.PLAY ? design : board;
    }

    /** Shows {@code loaded} (read from {@code from}) as the new, unmodified design, in the current mode. */
    public void load(Board loaded, Path from) {
        design = loaded.copy();
        saved = loaded.copy();
        board.replaceContents(loaded);
        file = from;
        sample = null;
        modified = false;
        linesLeftOut = 0;
        fireStateChanged();
    }

    /**
     * Shows {@code loaded}, read from {@code from} without {@code skippedLines} of its lines. That is a changed
     * board, unsaved: saving it over its file would remove those lines from the file.
     */
    public void loadWithout(Board loaded, Path from, int skippedLines) {
        load(loaded, from);
        linesLeftOut = skippedLines;
        modified = skippedLines > 0;
        fireStateChanged();
    }

    /** How many lines of the board's file saving over it would remove (lines skipped when it was loaded). */
    public int linesLostBySaving() {
        return linesLeftOut;
    }

    /** Shows the sample board {@code name} that came with the game: it has no file of its own. */
    public void loadSample(Board loaded, String name) {
        load(loaded, null);
        sample = name;
        fireStateChanged();
    }

    /** An empty, unsaved board. */
    public void newBoard() {
        load(new Board(), null);
    }

    /** The design was written to {@code to}. */
    public void saved(Path to) {
        saved = boardToSave().copy();
        file = to;
        sample = null;
        modified = false;
        linesLeftOut = 0;
        fireStateChanged();
    }

    /** Play mode: back to the design, as when play started. */
    public void reset() {
        if (mode == Mode.PLAY) {
            board.replaceContents(design);
        }
    }

    private void fireStateChanged() {
        stateListeners.forEach(Runnable::run);
    }
}
