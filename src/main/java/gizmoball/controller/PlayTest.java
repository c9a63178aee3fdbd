package gizmoball.controller;

import gizmoball.lab.Lab;
import gizmoball.lab.LabProgress;
import gizmoball.lab.LabResult;
import gizmoball.lab.LabSettings;
import gizmoball.model.Board;
import gizmoball.view.editor.PlayTestDialog;
import java.awt.Window;
import java.util.List;
import java.util.concurrent.ExecutionException;
import javax.swing.SwingWorker;

/**
 * Build mode's Play-test command: runs the board lab on a copy of the design in the background (a
 * {@link SwingWorker}, whose games play on the lab's own threads), so the window stays responsive, and shows its
 * progress and result in a {@link PlayTestDialog}. Cancel stops every game within a tick.
 */
public final class PlayTest {
    /** Games for each player: enough for the figures to settle, few enough to take seconds. */
    public static final int GAMES = 100;

    private final Worker worker;
    private final PlayTestDialog dialog;

    private PlayTest(Window owner, Board design, String boardName, LabSettings settings) {
        // Copied here, on the event thread, before any edit can change it under the lab.
        worker = new Worker(design.copy(), boardName, settings);
        dialog = PlayTestDialog.open(owner, boardName, () -> worker.cancel(true));
    }

    /** The lab's settings of the command: {@link #GAMES} games each on every core, with the lab's cap and tick. */
    public static LabSettings settings() {
        return LabSettings.of(GAMES);
    }

    /** Opens the Play-test window over {@code owner} and starts the lab on {@code design}; call on the event thread. */
    public static PlayTest start(Window owner, Board design, String boardName, LabSettings settings) {
        PlayTest test = new PlayTest(owner, design, boardName, settings);
        test.worker.execute();
        return test;
    }

    public PlayTestDialog dialog() {
        return dialog;
    }

    /** True once the lab has finished, failed or been cancelled. */
    public boolean isDone() {
        return worker.isDone();
    }

    /** The lab on its own threads; progress and the end are told to the dialog on the event thread. */
    private final class Worker extends SwingWorker<LabResult, int[]> {
        private final Board board;
        private final String boardName;
        private final LabSettings settings;

        Worker(Board board, String boardName, LabSettings settings) {
            this.board = board;
            this.boardName = boardName;
            this.settings = settings;
        }

        @Override
        protected LabResult doInBackground() {
            return Lab.run(board, boardName, settings, new LabProgress() {
                @Override
                public void gamesDone(int done, int total) {
                    publish(new int[] {done, total});
                }

                @Override
                public boolean cancelled() {
                    return isCancelled();
                }
            });
        }

        @Override
        protected void process(List<int[]> told) {
            int done = 0;
            int total = 0;
            for (int[] games : told) {
                // The lab's threads tell of their games in any order: the most games done is how far it is.
                if (games[0] > done) {
                    done = games[0];
                    total = games[1];
                }
            }
            if (!isCancelled() && done > 0) {
                dialog.progress(done, total);
            }
        }

        @Override
        protected void done() {
            if (isCancelled()) {
                dialog.cancelled();
                return;
            }
            try {
                dialog.finished(board, get());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                dialog.failed("interrupted");
            } catch (ExecutionException e) {
                dialog.failed(String.valueOf(e.getCause()));
            }
        }
    }
}
