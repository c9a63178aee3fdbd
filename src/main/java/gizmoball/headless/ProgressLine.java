package gizmoball.headless;

import gizmoball.lab.LabProgress;
import java.io.PrintStream;

/**
 * The lab's progress on one line of standard error, rewritten in place ("lab: 120/400 games") at each whole percent
 * (a later game first told is shown, an earlier one told after it not),
 * and ended with a newline when the last game is done.
 */
final class ProgressLine implements LabProgress {
    private final PrintStream err;
    private int percentShown = -1;
    /** The most games shown done: the threads may tell of their games out of order. */
    private int doneShown;

    ProgressLine(PrintStream err) {
        this.err = err;
    }

    @Override
    public synchronized void gamesDone(int done, int total) {
        int percent = (int) (100L * done / total);
        if (done > doneShown && percent != percentShown) {
            percentShown = percent;
            doneShown = done;
            err.print("\rlab: " + done + "/" + total + " games");
            if (done == total) {
                err.println();
            }
            err.flush();
        }
    }
}
