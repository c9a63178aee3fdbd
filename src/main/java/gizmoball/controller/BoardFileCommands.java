package gizmoball.controller;

import gizmoball.boardfile.AuthoredText;
import gizmoball.boardfile.BoardFileError;
import gizmoball.boardfile.BoardFiles;
import gizmoball.boardfile.FileErrors;
import gizmoball.boardfile.LoadResult;
import gizmoball.boardfile.SampleBoards;
import gizmoball.boardfile.SavePlan;
import gizmoball.session.GameSession;
import gizmoball.model.Board;
import gizmoball.view.LoadProblemsDialog;
import java.awt.Component;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import java.util.Optional;
import javax.swing.JFileChooser;
import javax.swing.JOptionPane;
import javax.swing.SwingUtilities;

/**
 * The File menu's work: choosing files, loading and saving through gizmoball.boardfile, and asking the
 * player before unsaved changes are lost. Every failure is shown to the player; a failed load leaves
 * the current board exactly as it was. A save keeps what the author wrote in the file the board came from
 * (its comments, blank lines and order: {@link AuthoredText}) and writes nothing when nothing changed; a new
 * board is written in the canonical form.
 */
public final class BoardFileCommands {
    private final Component window;
    private final Consumer<String> status;
    private final GameSession session;
    private final GameLoop loop;
    private static final String BOARD_EXTENSION = "txt";
    private static final String SAVE_AS = "Save As...";
    private static final String RELOAD = "Reload";
    private static final String CANCEL = "Cancel";

    private final JFileChooser chooser = new JFileChooser(Path.of("boards").toAbsolutePath().toFile());
    private final BoardFileFilter boardFiles = new BoardFileFilter();
    /** The text the shown board was read from or last saved as; null for a new board (saved canonically). */
    private AuthoredText authored;
    private final List<Consumer<Path>> folderListeners = new ArrayList<>();
    private final List<Consumer<Path>> fileListeners = new ArrayList<>();

    /** Dialogs open over {@code window}; outcomes are told to {@code status} (the status line). */
    public BoardFileCommands(Component window, Consumer<String> status, GameSession session, GameLoop loop) {
        this.window = window;
        this.status = status;
        this.session = session;
        this.loop = loop;
        chooser.setFileFilter(boardFiles);
    }

    /** The folder the file chooser opens in (the last one the player used, remembered between runs). */
    public void startIn(Path folder) {
        chooser.setCurrentDirectory(folder.toFile());
    }

    /**
     * Told the folder of each file the player chose in the file chooser (to open or to save): the folder the
     * chooser opens in next time. A board opened otherwise (at launch, a sample) is no choice of a folder.
     */
    public void addFolderListener(Consumer<Path> listener) {
        folderListeners.add(listener);
    }

    /** Told each file a board was loaded from or saved to (File > Open recent lists them). */
    public void addFileListener(Consumer<Path> listener) {
        fileListeners.add(listener);
    }

    /** File > Open recent: the file, after asking about unsaved changes. */
    public void openRecent(Path file) {
        if (confirmDiscard("open another board")) {
            open(file);
        }
    }

    public void newBoard() {
        if (confirmDiscard("start a new board")) {
            loop.stop();
            session.newBoard();
            authored = null;
            status.accept("New board");
        }
    }

    public void open() {
        if (confirmDiscard("open another board")
                && chooser.showOpenDialog(window) == JFileChooser.APPROVE_OPTION) {
            Path file = existing(chooser.getSelectedFile().toPath());
            chose(file);
            open(file);
        }
    }

    /**
     * The file meant by a name typed in the chooser: as typed if it exists, else with the extension Save As would
     * have given it ("xyz" for the "xyz.txt" saved as "xyz").
     */
    static Path existing(Path typed) {
        Path withExtension = withBoardExtension(typed, true);
        return !Files.exists(typed) && Files.isRegularFile(withExtension) ? withExtension : typed;
    }

    private void chose(Path file) {
        Path folder = file.toAbsolutePath().getParent();
        if (folder != null) {
            folderListeners.forEach(l -> l.accept(folder));
        }
        chooser.setSelectedFile(file.toFile());
    }

    /** Reload means "throw my changes away": asked as that, with Cancel the default, so Enter reverts nothing. */
    public void reload() {
        session.file().ifPresentOrElse(file -> {
            if (!session.isModified() || ask("Discard your changes to " + file.getFileName()
                    + " and reload it from disk?", "Reload", RELOAD, CANCEL) == 0) {
                open(file);
            }
        }, () -> status.accept("This board has no file to reload from"));
    }

    /**
     * Loads {@code file}. A file with bad lines opens the problems dialog: load without them (unless nothing
     * would be left), or keep the board shown now. Returns whether a board was loaded.
     */
    public boolean open(Path file) {
        String name = String.valueOf(file.getFileName());
        LoadResult result;
        try {
            result = BoardFiles.loadSkippingBadLines(file);
        } catch (IOException e) {
            error(FileErrors.cannotRead(file, e));
            return false;
        }
        List<BoardFileError> bad = result.skippedLines();
        if (bad.isEmpty()) {
            show(result, file, "Loaded " + name);
            showNotes(name, result);
            return true;
        }
        // A board empty because of skipping is not offered: one Save would write it over the whole file.
        if (!LoadProblemsDialog.askSkip(window, name, describe(bad), notes(result), !result.keptNothing())) {
            status.accept("Kept the current board; " + name + " has bad lines");
            return false;
        }
        show(result, file, "Loaded " + name + " without its " + lines(bad.size()));
        return true;
    }

    /**
     * Opens one of the sample boards inside the game as a new, untitled board: it has no file of its own,
     * so Save asks where to put it. Unsaved changes are asked about first.
     */
    public boolean openSample(String name) {
        if (!confirmDiscard("open the sample board " + name)) {
            return false;
        }
        Optional<String> text = SampleBoards.text(name);
        if (text.isEmpty()) {
            error("there is no sample board " + name + " inside this build of the game");
            return false;
        }
        LoadResult result = BoardFiles.loadSkippingBadLines(name, text.get());
        if (!result.skippedLines().isEmpty()) {
            error("the sample board " + name + " does not load: " + result.skippedLines().get(0));
            return false;
        }
        loop.stop();
        session.loadSample(result.board(), name);
        authored = result.authored();
        status.accept("Opened the sample board " + name + "; Save As keeps a copy");
        return true;
    }

    /**
     * Loads the board the window opens on. A clean file is shown at once; a problem (and its dialog) waits
     * until the window is up, so that whoever opened the window is not blocked by a modal dialog.
     */
    public void openAtLaunch(Path file) {
        String name = String.valueOf(file.getFileName());
        try {
            LoadResult result = BoardFiles.loadSkippingBadLines(file);
            if (result.skippedLines().isEmpty()) {
                show(result, file, "Loaded " + name);
                SwingUtilities.invokeLater(() -> showNotes(name, result));
                return;
            }
        } catch (IOException e) {
            // reported by open, once the window is up
        }
        SwingUtilities.invokeLater(() -> open(file));
    }

    /** A file that loaded as it is may still have notes: they are shown, after the board. */
    private void showNotes(String name, LoadResult result) {
        if (!result.notes().isEmpty()) {
            LoadProblemsDialog.showNotes(window, name, notes(result));
        }
    }

    /**
     * Saves to the board's file, or asks for one. A save that would remove lines of the file beyond those of what
     * the player deleted (lines left out when it was loaded; comments it cannot keep) is asked first, naming every
     * line that would go and offering Save As. Returns whether the board was saved.
     */
    public boolean save() {
        Optional<Path> file = session.file();
        if (file.isEmpty()) {
            return saveAs();
        }
        SavePlan plan = plan();
        SavePlan.LostLines lost = plan.lost();
        if (lost.total() > 0) {
            String name = String.valueOf(file.get().getFileName());
            String why = lost.badLines() == lost.total() ? "left out when it was loaded"
                    : "that the edited board cannot be written around";
            int choice = ask("Saving over " + name + " removes " + lost.describe() + " from it, " + why + ".",
                    "Save would lose lines", SAVE_AS, "Save and lose " + lost.describe(), CANCEL);
            return switch (choice) {
                case 0 -> saveAs();
                case 1 -> saveTo(file.get(), plan);
                default -> false;
            };
        }
        return saveTo(file.get(), plan);
    }

    /**
     * Asks for a file and saves there. A name without an extension gets .txt while the board-files filter is
     * chosen; an existing file is replaced only if the player says so, and otherwise the chooser comes back for
     * another name.
     */
    public boolean saveAs() {
        chooser.setSelectedFile(session.file().map(Path::toFile)
                .orElseGet(() -> chooser.getCurrentDirectory().toPath().resolve(session.suggestedFileName()).toFile()));
        while (chooser.showSaveDialog(window) == JFileChooser.APPROVE_OPTION) {
            Path file = withBoardExtension(chooser.getSelectedFile().toPath(), chooser.getFileFilter() == boardFiles);
            if (!Files.exists(file) || ask(file.getFileName() + " already exists. Replace it?", "Save As",
                    "Replace", CANCEL) == 0) {
                chose(file);
                return saveTo(file, plan());
            }
        }
        return false;
    }

    /** What saving the design writes: over the text it came from, or canonical for a new board. */
    private SavePlan plan() {
        Board board = session.boardToSave();
        return authored == null ? SavePlan.canonical(board) : authored.saving(board);
    }

    /** {@code file} with ".txt" added if it has no extension and {@code boardFilter} (the chooser's) applies. */
    static Path withBoardExtension(Path file, boolean boardFilter) {
        String name = String.valueOf(file.getFileName());
        boolean hasExtension = name.lastIndexOf('.') > 0;
        return boardFilter && !hasExtension ? file.resolveSibling(name + "." + BOARD_EXTENSION) : file;
    }

    /**
     * True when nothing unsaved would be lost by {@code doing}, or the player saved it or agreed to lose it.
     */
    public boolean confirmDiscard(String doing) {
        if (!session.isModified()) {
            return true;
        }
        Object[] choices = {"Save", "Discard", "Cancel"};
        int choice = JOptionPane.showOptionDialog(window,
                session.boardName() + " has unsaved changes. Save them before you " + doing + "?",
                "Unsaved changes", JOptionPane.YES_NO_CANCEL_OPTION, JOptionPane.WARNING_MESSAGE, null, choices,
                choices[0]);
        return switch (choice) {
            case 0 -> save();
            case 1 -> true;
            default -> false;
        };
    }

    private boolean saveTo(Path file, SavePlan plan) {
        try {
            boolean wrote = BoardFiles.save(plan, file);
            session.saved(file);
            authored = plan.saved();
            fileListeners.forEach(l -> l.accept(file));
            status.accept(wrote ? "Saved " + file.getFileName() : file.getFileName() + " already holds this board:"
                    + " nothing to write");
            return true;
        } catch (IOException e) {
            error(FileErrors.cannotSave(file, e) + (Files.exists(file) ? ". The file on disk is unchanged." : ""));
            return false;
        }
    }

    private void show(LoadResult loaded, Path file, String message) {
        loop.stop();
        session.loadWithout(loaded.board(), file, loaded.skippedLines().size());
        authored = loaded.authored();
        status.accept(message);
        fileListeners.forEach(l -> l.accept(file));
    }

    /** Shows a lower-case sentence of FileErrors (shared with the headless runner) as the player reads it. */
    private void error(String sentence) {
        String message = Character.toUpperCase(sentence.charAt(0)) + sentence.substring(1);
        status.accept(message);
        JOptionPane.showMessageDialog(window, message, "Gizmoball", JOptionPane.ERROR_MESSAGE);
    }

    private static List<String> describe(List<BoardFileError> errors) {
        return errors.stream()
                .map(e -> "line " + e.line() + ": " + e.text().strip() + LoadProblemsDialog.BECAUSE + e.reason())
                .toList();
    }

    private static List<String> notes(LoadResult result) {
        return result.notes().stream()
                .map(n -> "line " + n.line() + ": " + n.text().strip() + LoadProblemsDialog.BECAUSE + n.note())
                .toList();
    }

    /** A question with these buttons, the last (Cancel) the default; the index of the one chosen, -1 if closed. */
    private int ask(String question, String title, String... choices) {
        return JOptionPane.showOptionDialog(window, question, title, JOptionPane.DEFAULT_OPTION,
                JOptionPane.WARNING_MESSAGE, null, choices, choices[choices.length - 1]);
    }

    private static String lines(int count) {
        return count + (count == 1 ? " bad line" : " bad lines");
    }
}
