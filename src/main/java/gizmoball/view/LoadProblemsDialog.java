package gizmoball.view;

import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.FlowLayout;
import java.awt.Font;
import java.awt.Window;
import java.util.List;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.SwingUtilities;

/**
 * Tells the player why a board file could not be loaded, line by line, and asks whether to load it
 * without those lines or to keep the board shown now.
 */
public final class LoadProblemsDialog extends JDialog {
    public static final String SKIP = "Load skipping these lines";
    public static final String KEEP = "Keep current board";

    private boolean skip;

    private LoadProblemsDialog(Component parent, String fileName, List<String> problems, boolean skippable) {
        super(parent instanceof Window w ? w : SwingUtilities.getWindowAncestor(parent), "Problems in " + fileName,
                ModalityType.APPLICATION_MODAL);
        setName("loadProblems");
        JLabel heading = new JLabel(!skippable
                ? "Nothing in " + fileName + " can be loaded:"
                : problems.size() == 1
                ? fileName + " has a line that cannot be loaded:"
                : fileName + " has " + problems.size() + " lines that cannot be loaded:");
        heading.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        JList<String> list = new JList<>(problems.toArray(String[]::new));
        list.setName("loadProblems.list");
        list.setFont(new Font(Font.MONOSPACED, Font.PLAIN, list.getFont().getSize()));
        list.setVisibleRowCount(Math.min(12, Math.max(3, problems.size())));
        JButton skipButton = new JButton(SKIP);
        skipButton.addActionListener(e -> close(true));
        JButton keepButton = new JButton(KEEP);
        keepButton.addActionListener(e -> close(false));
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        if (skippable) {
            buttons.add(skipButton);
        }
        buttons.add(keepButton);
        add(heading, BorderLayout.NORTH);
        add(new JScrollPane(list), BorderLayout.CENTER);
        add(buttons, BorderLayout.SOUTH);
        getRootPane().setDefaultButton(keepButton);
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);
        pack();
        setSize(Math.min(getWidth(), 900), getHeight());
        setLocationRelativeTo(parent);
    }

    /**
     * Blocks (modal) until the player chooses; true to load skipping the lines. Closing the dialog keeps the
     * board. Unless {@code skippable} (skipping would leave nothing), keeping the board is the only choice.
     */
    public static boolean askSkip(Component parent, String fileName, List<String> problems, boolean skippable) {
        LoadProblemsDialog dialog = new LoadProblemsDialog(parent, fileName, problems, skippable);
        dialog.setVisible(true);
        return dialog.skip;
    }

    private void close(boolean skipLines) {
        skip = skipLines;
        dispose();
    }
}
