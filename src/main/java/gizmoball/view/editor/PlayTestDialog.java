package gizmoball.view.editor;

import gizmoball.lab.LabReport;
import gizmoball.lab.LabResult;
import gizmoball.lab.PlayerReport;
import gizmoball.model.Board;
import gizmoball.view.HeatMapPicture;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Font;
import java.awt.Window;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.ImageIcon;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.WindowConstants;

/**
 * Build mode's Play-test window: while the lab plays, a progress bar and Cancel; when it is done, the heat map of the
 * autoplayer's games over the board beside the key figures (mean scores of the autoplayer and the idle player,
 * seconds per ball, whether the flippers matter, the gizmos never hit, drains and jams). It only shows: whoever
 * runs the lab tells it how far it is and what came of it, and is told when the player cancels.
 */
public final class PlayTestDialog extends JDialog {
    private static final long serialVersionUID = 1L;
    /** Pixels across the heat map. */
    static final int HEAT_MAP_SIDE = 480;

    private final JProgressBar progress = new JProgressBar();
    private final JLabel status = new JLabel("Starting\u2026");
    private final JButton button = new JButton("Cancel");
    private final JPanel results = new JPanel(new BorderLayout(12, 0));
    private final Runnable cancel;
    private boolean running = true;

    private PlayTestDialog(Window owner, String boardName, Runnable cancel) {
        super(owner, "Play-test: " + boardName, ModalityType.MODELESS);
        this.cancel = cancel;
        setName("playtest");
        progress.setName("playtest.progress");
        progress.setStringPainted(true);
        status.setName("playtest.status");
        button.setName("playtest.cancel");
        results.setName("playtest.results");
        button.addActionListener(e -> cancelOrClose());
        setDefaultCloseOperation(WindowConstants.DO_NOTHING_ON_CLOSE);

        JPanel top = new JPanel(new BorderLayout(8, 4));
        top.setBorder(BorderFactory.createEmptyBorder(10, 10, 6, 10));
        top.add(status, BorderLayout.NORTH);
        top.add(progress, BorderLayout.CENTER);
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        buttons.add(button);
        top.add(buttons, BorderLayout.EAST);
        results.setBorder(BorderFactory.createEmptyBorder(0, 10, 10, 10));
        getContentPane().add(top, BorderLayout.NORTH);
        getContentPane().add(results, BorderLayout.CENTER);
        setMinimumSize(new Dimension(560, 120));
        pack();
        setLocationRelativeTo(owner);
    }

    /**
     * A Play-test window over {@code owner}, shown, running: {@code cancel} is called (on the event thread) when the
     * player presses Cancel or closes it while the lab plays.
     */
    public static PlayTestDialog open(Window owner, String boardName, Runnable cancel) {
        PlayTestDialog dialog = new PlayTestDialog(owner, boardName, cancel);
        dialog.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                dialog.cancelOrClose();
            }
        });
        dialog.setVisible(true);
        return dialog;
    }

    private void cancelOrClose() {
        if (running) {
            cancel.run();
        } else {
            dispose();
        }
    }

    /** {@code done} of {@code total} games are played (told out of order, an earlier count is passed over). */
    public void progress(int done, int total) {
        if (!running || done <= progress.getValue() && total == progress.getMaximum()) {
            return;
        }
        progress.setMaximum(total);
        progress.setValue(done);
        progress.setString(done + " / " + total + " games");
        status.setText("Playing with an autoplayer and with a player who only launches\u2026");
    }

    /** The lab stopped at the player's word. */
    public void cancelled() {
        finish("Cancelled after " + progress.getValue() + " of " + progress.getMaximum() + " games.");
    }

    /** The lab failed: {@code why}. */
    public void failed(String why) {
        finish("The play-test failed: " + why);
    }

    /** The lab is done: shows the heat map of {@code board} and the figures. */
    public void finished(Board board, LabResult result) {
        LabReport report = result.report();
        String verdict = report.verdictLine();
        finish(Character.toUpperCase(verdict.charAt(0)) + verdict.substring(1) + ".");
        JLabel map = new JLabel(new ImageIcon(HeatMapPicture.image(board, result.autoplayerHeat(), HEAT_MAP_SIDE,
                report.heatMapCaption())));
        map.setName("playtest.heatmap");
        JTextArea figures = new JTextArea(figures(report));
        figures.setName("playtest.figures");
        figures.setEditable(false);
        figures.setLineWrap(true);
        figures.setWrapStyleWord(true);
        figures.setFont(figures.getFont().deriveFont(Font.PLAIN));
        figures.setColumns(34);
        results.add(map, BorderLayout.WEST);
        results.add(new JScrollPane(figures), BorderLayout.CENTER);
        pack();
        setLocationRelativeTo(getOwner());
    }

    private void finish(String message) {
        running = false;
        status.setText(message);
        button.setText("Close");
    }

    /** The figures an author tunes by, in words. */
    static String figures(LabReport report) {
        PlayerReport auto = report.autoplayer();
        PlayerReport idle = report.idle();
        StringBuilder text = new StringBuilder();
        text.append(String.format(Locale.ROOT, "%d games each, at most %.0f s of play.%n%n", report.gamesPerPlayer(),
                report.gameCapSeconds()));
        text.append(String.format(Locale.ROOT, "Mean score: autoplayer %.0f (spread %.0f, %d to %d), idle %.0f"
                        + " (spread %.0f)%s.%n", auto.score().mean(), auto.score().standardDeviation(),
                (long) auto.score().min(), (long) auto.score().max(), idle.score().mean(),
                idle.score().standardDeviation(), report.autoplayerOverIdle() == null ? ""
                        : String.format(Locale.ROOT, ": %.2fx", report.autoplayerOverIdle())));
        text.append(String.format(Locale.ROOT, "A ball lasts: autoplayer %.1f s (spread %.1f), idle %.1f s"
                        + " (spread %.1f).%n", auto.secondsPerBall().mean(), auto.secondsPerBall().standardDeviation(),
                idle.secondsPerBall().mean(), idle.secondsPerBall().standardDeviation()));
        text.append(String.format(Locale.ROOT, "Idle games end on %d different scores.%n%n", idle.distinctScores()));
        text.append("Never hit by the autoplayer: ").append(auto.neverHit().isEmpty() ? "none"
                : String.join(", ", auto.neverHit())).append(".\n\n");
        for (PlayerReport.DrainReport drain : auto.drains()) {
            text.append(String.format(Locale.ROOT, "Drained into %s: %d balls.%n", drain.place(), drain.balls()));
        }
        if (auto.jams().balls() > 0) {
            PlayerReport.JamPlace worst = auto.jams().places().get(0);
            text.append(String.format(Locale.ROOT, "Jammed: %d balls in %d games, most at cell (%d, %d).%n",
                    auto.jams().balls(), auto.jams().games(), worst.x(), worst.y()));
        }
        if (auto.gamesAtCap() > 0) {
            text.append(String.format(Locale.ROOT, "%d autoplayer games were still going at the cap.%n",
                    auto.gamesAtCap()));
        }
        return text.toString();
    }
}
