package gizmoball.controller;

import gizmoball.boardfile.BoardFileError;
import gizmoball.boardfile.BoardFileException;
import gizmoball.boardfile.BoardFiles;
import gizmoball.boardfile.LoadResult;
import gizmoball.session.GameSession;
import gizmoball.model.Board;
import gizmoball.view.LoadProblemsDialog;
import java.awt.Component;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import javax.swing.JFileChooser;
import javax.swing.JOptionPane;
import javax.swing.SwingUtilities;
import javax.swing.filechooser.FileNameExtensionFilter;

/**
 * The File menu's work: choosing files, loading and saving through gizmoball.boardfile, and asking the
 * player before unsaved changes are lost. Every failure is shown to the player; a failed load leaves
 * the current board exactly as it was.
 */
public final class BoardFileCommands {
    private final Component window;
    private final Consumer<String> status;
    private final GameSession session;
    private final GameLoop loop;
    private final JFileChooser chooser = new JFileChooser(Path.of("boards").toAbsolutePath().toFile());

    /** Dialogs open over {@code window}; outcomes are told to {@code status} (the status line). */
    public BoardFileCommands(Component window, Consumer<String> status, GameSession session, GameLoop loop) {
        this.window = window;
        this.status = status;
        this.session = session;
        this.loop = loop;
        chooser.setFileFilter(new FileNameExtensionFilter("Board files (.txt, .gizmo)", "txt", "gizmo"));
    }

    public void newBoard() {
        if (confirmDiscard("start a new board")) {
            loop.stop();
            session.newBoard();
            status.accept("New board");
        }
    }

    public void open() {
        if (confirmDiscard("open another board")
                && chooser.showOpenDialog(window) == JFileChooser.APPROVE_OPTION) {
            open(chooser.getSelectedFile().toPath());
        }
    }

    public void reload() {
        session.file().ifPresentOrElse(file -> {
            if (confirmDiscard("reload it from " + file.getFileName())) {
                open(file);
            }
        }, () -> status.accept("This board has no file to reload from"));
    }

    /**
     * Loads {@code file}. A file with bad lines opens the problems dialog: load without them, or keep the
     * board shown now. Returns whether a board was loaded.
     */
    public boolean open(Path file) {
        String name = String.valueOf(file.getFileName());
        try {
            try {
                show(BoardFiles.load(file), file, "Loaded " + name);
                return true;
            } catch (BoardFileException e) {
                if (!LoadProblemsDialog.askSkip(window, name, describe(e.errors()))) {
                    status.accept("Kept the current board; " + name + " has bad lines");
                    return false;
                }
                LoadResult result = BoardFiles.loadSkippingBadLines(file);
                int skipped = result.skippedLines().size();
                show(result.board(), file, "Loaded " + name + " without its " + skipped
                        + (skipped == 1 ? " bad line" : " bad lines"));
                return true;
            }
        } catch (IOException e) {
            error("Cannot read " + file + ": " + reason(e));
            return false;
        }
    }

    /**
     * Loads the board the window opens on. A clean file is shown at once; a problem (and its dialog) waits
     * until the window is up, so that whoever opened the window is not blocked by a modal dialog.
     */
    public void openAtLaunch(Path file) {
        try {
            show(BoardFiles.load(file), file, "Loaded " + file.getFileName());
        } catch (BoardFileException | IOException e) {
            SwingUtilities.invokeLater(() -> open(file));
        }
    }

    /** Saves to the board's file, or asks for one. Returns whether the board was saved. */
    public boolean save() {
        return session.file().map(this::saveTo).orElseGet(this::saveAs);
    }

    public boolean saveAs() {
        session.file().ifPresent(f -> chooser.setSelectedFile(f.toFile()));
        if (chooser.showSaveDialog(window) != JFileChooser.APPROVE_OPTION) {
            return false;
        }
        Path file = chooser.getSelectedFile().toPath();
        if (Files.exists(file) && JOptionPane.showConfirmDialog(window, file.getFileName() + " exists. Replace it?",
                "Save As", JOptionPane.OK_CANCEL_OPTION, JOptionPane.WARNING_MESSAGE) != JOptionPane.OK_OPTION) {
            return false;
        }
        return saveTo(file);
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

    private boolean saveTo(Path file) {
        try {
            BoardFiles.save(session.boardToSave(), file);
            session.saved(file);
            status.accept("Saved " + file.getFileName());
            return true;
        } catch (IOException e) {
            error("Cannot save " + file + ": " + reason(e) + ". The file on disk is unchanged.");
            return false;
        }
    }

    private void show(Board board, Path file, String message) {
        loop.stop();
        session.load(board, file);
        status.accept(message);
    }

    private void error(String message) {
        status.accept(message);
        JOptionPane.showMessageDialog(window, message, "Gizmoball", JOptionPane.ERROR_MESSAGE);
    }

    private static List<String> describe(List<BoardFileError> errors) {
        return errors.stream().map(e -> "line " + e.line() + ": " + e.text().strip() + "   <- " + e.reason()).toList();
    }

    private static String reason(IOException e) {
        if (e instanceof NoSuchFileException) {
            return "no such file";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
    }
}
