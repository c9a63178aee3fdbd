package gizmoball.view;

import gizmoball.highscore.HighScore;
import gizmoball.highscore.HighScoreTable;
import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.text.NumberFormat;
import java.util.Locale;
import java.util.Optional;
import java.util.function.Consumer;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.ListSelectionModel;
import javax.swing.SwingUtilities;
import javax.swing.table.DefaultTableModel;

/** A board's top ten (place, name, score, date), from which an entry's game can be watched again. */
public final class HighScoresDialog {
    private HighScoresDialog() {
    }

    /**
     * Shows the table (modal); Watch (or a double click) closes it and hands the chosen entry to {@code watch}, and
     * "Replay file..." to {@code watchFile}.
     */
    public static void show(Component parent, String boardName, HighScoreTable table, Optional<String> problem,
                            Consumer<HighScore> watch, Runnable watchFile) {
        JDialog dialog = new JDialog(SwingUtilities.getWindowAncestor(parent), "High scores of " + boardName,
                JDialog.DEFAULT_MODALITY_TYPE);
        dialog.setName("highscores.dialog");
        DefaultTableModel model = new DefaultTableModel(new Object[] {"#", "Name", "Score", "Date"}, 0) {
            private static final long serialVersionUID = 1L;

            @Override
            public boolean isCellEditable(int row, int column) {
                return false;
            }
        };
        NumberFormat number = NumberFormat.getIntegerInstance(Locale.ROOT);
        for (int i = 0; i < table.entries().size(); i++) {
            HighScore entry = table.entries().get(i);
            model.addRow(new Object[] {i + 1, entry.name(), number.format(entry.score()), entry.date().toString()});
        }
        JTable rows = new JTable(model);
        rows.setName("highscores.table");
        rows.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        rows.setFillsViewportHeight(true);
        rows.getColumnModel().getColumn(0).setMaxWidth(40);
        if (!table.entries().isEmpty()) {
            rows.setRowSelectionInterval(0, 0);
        }
        JButton watchButton = new JButton("Watch");
        watchButton.setName("highscores.watch");
        watchButton.setEnabled(!table.entries().isEmpty());
        Runnable watchSelected = () -> {
            int row = rows.getSelectedRow();
            if (row >= 0) {
                dialog.dispose();
                watch.accept(table.entries().get(row));
            }
        };
        watchButton.addActionListener(e -> watchSelected.run());
        rows.addMouseListener(new MouseAdapter() {
            @Override
            public void mouseClicked(MouseEvent e) {
                if (e.getClickCount() == 2) {
                    watchSelected.run();
                }
            }
        });
        JButton fileButton = new JButton("Replay file...");
        fileButton.setName("highscores.file");
        fileButton.addActionListener(e -> {
            dialog.dispose();
            watchFile.run();
        });
        JButton close = new JButton("Close");
        close.addActionListener(e -> dialog.dispose());
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        buttons.add(watchButton);
        buttons.add(fileButton);
        buttons.add(close);
        JPanel content = new JPanel(new BorderLayout(0, 8));
        content.setBorder(BorderFactory.createEmptyBorder(10, 10, 10, 10));
        String says = problem.orElse(table.entries().isEmpty() ? "No high score on this board yet: play a game to the"
                + " end." : "Watch replays an entry's game in the window, exactly as it was played.");
        JLabel note = new JLabel("<html>" + says + "</html>");
        note.setName("highscores.note");
        content.add(note, BorderLayout.NORTH);
        JScrollPane scroll = new JScrollPane(rows);
        scroll.setPreferredSize(new Dimension(420, 230));
        content.add(scroll, BorderLayout.CENTER);
        content.add(buttons, BorderLayout.SOUTH);
        dialog.setContentPane(content);
        dialog.getRootPane().setDefaultButton(watchButton.isEnabled() ? watchButton : close);
        dialog.setDefaultCloseOperation(JDialog.DISPOSE_ON_CLOSE);
        EscapeCloses.install(dialog);
        dialog.pack();
        dialog.setLocationRelativeTo(parent);
        dialog.setVisible(true);
    }
}
