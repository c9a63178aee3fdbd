package gizmoball.view;

import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.FlowLayout;
import java.awt.Font;
import java.awt.GridLayout;
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
 * without those lines or to keep the board shown now. Under their own heading it lists the notes: lines
 * written in another implementation's way and how they were read. A file with notes only loads as it is;
 * the dialog then just reports them.
 */
public final class LoadProblemsDialog extends JDialog {
    public static final String SKIP = "Load skipping these lines";
    public static final String KEEP = "Keep current board";
    public static final String OK = "OK";
    private static final int MOST_ROWS = 12;

    private boolean skip;

    private LoadProblemsDialog(Component parent, String fileName, List<String> problems, List<String> notes,
                               boolean skippable) {
        super(parent instanceof Window w ? w : SwingUtilities.getWindowAncestor(parent),
                (problems.isEmpty() ? "Notes on " : "Problems in ") + fileName, ModalityType.APPLICATION_MODAL);
        setName("loadProblems");
        JPanel sections = new JPanel(new GridLayout(0, 1));
        if (!problems.isEmpty()) {
            sections.add(section(!skippable
                    ? "Nothing in " + fileName + " can be loaded:"
                    : problems.size() == 1
                    ? fileName + " has a line that cannot be loaded:"
                    : fileName + " has " + problems.size() + " lines that cannot be loaded:", problems, "loadProblems"));
        }
        if (!notes.isEmpty()) {
            sections.add(section((notes.size() == 1 ? "A note" : notes.size() + " notes")
                    + ": lines written for another Gizmoball, read as it meant them", notes, "loadProblems.notes"));
        }
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        JButton close;
        if (problems.isEmpty()) {
            close = button(OK, false);
        } else {
            if (skippable) {
                buttons.add(button(SKIP, true));
            }
            close = button(KEEP, false);
        }
        buttons.add(close);
        add(sections, BorderLayout.CENTER);
        add(buttons, BorderLayout.SOUTH);
        getRootPane().setDefaultButton(close);
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);
        EscapeCloses.install(this);
        pack();
        setSize(Math.min(getWidth(), 900), getHeight());
        setLocationRelativeTo(parent);
    }

    /** A heading over its list of lines; the list is named {@code name}.list. */
    private static JPanel section(String heading, List<String> lines, String name) {
        JLabel label = new JLabel(heading);
        label.setName(name + ".heading");
        label.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        JList<String> list = new JList<>(lines.toArray(String[]::new));
        list.setName(name + ".list");
        list.setFont(new Font(Font.MONOSPACED, Font.PLAIN, list.getFont().getSize()));
        list.setVisibleRowCount(Math.min(MOST_ROWS, Math.max(3, lines.size())));
        JPanel section = new JPanel(new BorderLayout());
        section.add(label, BorderLayout.NORTH);
        section.add(new JScrollPane(list), BorderLayout.CENTER);
        return section;
    }

    private JButton button(String text, boolean skipLines) {
        JButton button = new JButton(text);
        button.addActionListener(e -> close(skipLines));
        return button;
    }

    /**
     * Blocks (modal) until the player chooses; true to load skipping the lines. Closing the dialog keeps the
     * board. Unless {@code skippable} (skipping would leave nothing), keeping the board is the only choice.
     * The notes are listed under their own heading.
     */
    public static boolean askSkip(Component parent, String fileName, List<String> problems, List<String> notes,
                                  boolean skippable) {
        LoadProblemsDialog dialog = new LoadProblemsDialog(parent, fileName, problems, notes, skippable);
        dialog.setVisible(true);
        return dialog.skip;
    }

    /** Blocks (modal) until the player has read the notes of a file that loaded. */
    public static void showNotes(Component parent, String fileName, List<String> notes) {
        new LoadProblemsDialog(parent, fileName, List.of(), notes, false).setVisible(true);
    }

    private void close(boolean skipLines) {
        skip = skipLines;
        dispose();
    }
}
